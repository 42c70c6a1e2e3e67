#include "reports/timeline_svg.h"

#include <gtest/gtest.h>

#include <string>

namespace skinsim::reports {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

// Two passes as the cost model schedules them: B's TA (2-6) overlaps A's 3D (2-7); a blur-like
// pass C has no TA work; the frame waits 1 ms on DRAM after the pipeline.
std::vector<results::PassCost> frame() {
  results::PassCost a{"a", 7.0, "alu", {}, 0.0, 2.0, 2.0, 7.0};
  results::PassCost b{"b<&>", 1.0, "tiler", {}, 2.0, 6.0, 7.0, 8.0};
  results::PassCost c{"c", 1.0, "texture", {}, 7.0, 7.0, 8.0, 9.0};
  results::PassCost wait{"dram_wait", 1.0, "bandwidth", {}, 9.0, 9.0, 9.0, 10.0};
  return {a, b, c, wait};
}

TEST(TimelineSvg, OneBoxPerStageWithWorkAndOneLegendEntryPerPass) {
  const std::string svg = timeline_svg(frame(), {"a", "b<&>", "c"});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u) << svg;
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  // TA boxes for a and b; 3D boxes for a, b, c and the DRAM wait: six tooltips.
  EXPECT_EQ(count(svg, "<title>"), 6u) << svg;
  EXPECT_NE(svg.find("b&lt;&amp;&gt;: TA 2.000-6.000 ms, 3D 7.000-8.000 ms"), std::string::npos)
      << svg;
  EXPECT_EQ(svg.find("b<&>"), std::string::npos) << "names are escaped";
  for (const char* legend :
       {"a 7.00 ms", "b&lt;&amp;&gt; 1.00 ms", "c 1.00 ms", "dram_wait 1.00 ms"}) {
    EXPECT_NE(svg.find(legend), std::string::npos) << legend;
  }
  EXPECT_NE(svg.find("the frame ends at 10.00 ms"), std::string::npos) << svg;
  EXPECT_NE(svg.find("fill=\"#808080\""), std::string::npos) << "the DRAM wait is grey";
}

TEST(TimelineSvg, EmptyFrameIsStillAValidPicture) {
  const std::string svg = timeline_svg({}, {});
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(count(svg, "<title>"), 0u);
}

}  // namespace
}  // namespace skinsim::reports
