#include <gtest/gtest.h>

#include "pipeline/config.h"

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

TEST(PipelineConfig, DefaultsAreValid) { EXPECT_NO_THROW(PipelineConfig{}.validate()); }

TEST(PipelineConfig, OutOfRangeValuesNameTheField) {
  EXPECT_NE(error_of("scale", "0").find("buffer_scale"), std::string::npos);
  EXPECT_NE(error_of("scale", "1.01").find("buffer_scale"), std::string::npos);
  EXPECT_NE(error_of("scale", "abc").find("scale"), std::string::npos);
  EXPECT_NE(error_of("lut", "33x128").find("lut width"), std::string::npos);
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
