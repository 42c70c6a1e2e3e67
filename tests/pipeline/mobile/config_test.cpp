#include "pipeline/config.h"

#include <gtest/gtest.h>

namespace skinsim::pipeline {
namespace {

std::string error_of(const std::string& key, const std::string& value) {
  PipelineConfig c;
  try {
    set_config_field(c, key, value);
    c.validate();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// Only plain decimal numbers are knob values: each of these must be refused, naming the knob.
TEST(PipelineConfig, RefusesNumbersThatAreNotPlainFiniteDecimals) {
  const std::pair<const char*, const char*> cases[] = {{"scale", "nan"},
                                                       {"scale", "inf"},
                                                       {"scale", "-inf"},
                                                       {"scale", "1e308"},
                                                       {"scale", "0x10"},
                                                       {"scale", " 0.5"},
                                                       {"scale", "0.5 "},
                                                       {"scale", ""},
                                                       {"scale", "+0.5"},
                                                       {"blur_iterations", "0x2"},
                                                       {"blur_iterations", "2.0"},
                                                       {"blur_iterations", "4294967298"},
                                                       {"blur_iterations", " 2"},
                                                       {"lut", "0x20x128"},
                                                       {"lut", "32x 128"},
                                                       {"lobe1", "0.3,nan"},
                                                       {"burley_distance_mm", "1,inf,1"}};
  for (const auto& [key, value] : cases) {
    const std::string message = error_of(key, value);
    EXPECT_NE(message.find(key), std::string::npos) << key << "='" << value << "': " << message;
  }
  EXPECT_EQ(error_of("scale", "5e-1"), "");
  EXPECT_EQ(error_of("blur_iterations", "2"), "");
}

TEST(PipelineConfig, RangeMessagesPrintValuesReadably) {
  EXPECT_EQ(error_of("scale", "1e30"), "scale must be in (0, 1], got 1e+30");
}

TEST(PipelineConfig, DefaultsAreValid) {
  EXPECT_NO_THROW(PipelineConfig{}.validate());
}

TEST(PipelineConfig, OutOfRangeValuesNameTheField) {
  EXPECT_NE(error_of("scale", "0").find("scale must be in (0, 1]"), std::string::npos);
  EXPECT_NE(error_of("scale", "1.01").find("scale must be in (0, 1]"), std::string::npos);
  EXPECT_NE(error_of("scale", "abc").find("scale"), std::string::npos);
  EXPECT_NE(
      error_of("lut", "33x128").find("lut must be powers of two in [2, 1024] per axis, got 33x128"),
      std::string::npos);
  EXPECT_NE(error_of("lut", "32xx").find("lut"), std::string::npos);
  EXPECT_NE(error_of("lut_format", "rgba32f").find("lut_format"), std::string::npos);
  EXPECT_NE(error_of("lut_format", "bgr").find("lut_format"), std::string::npos);
  EXPECT_NE(error_of("blur_iterations", "0").find("blur_iterations"), std::string::npos);
  EXPECT_NE(error_of("gamma", "2.2").find("gamma"), std::string::npos);
  EXPECT_NE(error_of("lobe1", "0.3").find("lobe1"), std::string::npos);
  EXPECT_NE(error_of("lobe1", "0.3,0.5").find("sum to 1"), std::string::npos);
  EXPECT_NE(error_of("resolution", "8x8").find("resolution"), std::string::npos);
  EXPECT_NE(error_of("no_such_knob", "1").find("unknown pipeline setting"), std::string::npos);
}

TEST(PipelineConfig, EveryFieldRoundTripsThroughText) {
  PipelineConfig c;
  set_config_field(c, "scale", "0.25");
  set_config_field(c, "lut", "64x256");
  set_config_field(c, "lut_format", "rgba16f");
  set_config_field(c, "resolution", "640x480");
  for (const std::string& key : config_field_names()) {
    PipelineConfig copy;
    set_config_field(copy, key, get_config_field(c, key));
    EXPECT_EQ(get_config_field(copy, key), get_config_field(c, key)) << key;
  }
  EXPECT_EQ(get_config_field(c, "lut"), "64x256");
}

}  // namespace
}  // namespace skinsim::pipeline
