// The page (viewer/src/page.cpp): viewer/web/viewer.html with the title, the data and the three
// scripts put in place of their markers, once each, nothing left of a marker, and a title that
// cannot break out of its element.
#include <gtest/gtest.h>

#include <string>

#include "page.hpp"

namespace stride::viewer {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(viewer_page, every_marker_is_filled_once_and_the_title_is_escaped) {
  const std::string data = R"({"title":"x","marker":"@STRIDE_DATA@"})";
  const std::string html = render_page("run <b>&</b>", data);
  EXPECT_EQ(html.find("@STRIDE_TITLE@"), std::string::npos);
  EXPECT_EQ(html.find("@STRIDE_THREE@"), std::string::npos);
  EXPECT_EQ(html.find("@STRIDE_FK@"), std::string::npos);
  EXPECT_EQ(html.find("@STRIDE_VIEWER@"), std::string::npos);
  // the data as given, once, in its element; a marker inside it is not filled again
  EXPECT_EQ(
      count(html, R"(<script type="application/json" id="stride-data">)" + data + "</script>"), 1u);
  EXPECT_NE(html.find("<title>run &lt;b&gt;&amp;&lt;/b&gt;</title>"), std::string::npos);
  // three.js's module (its license header and the renderer), fk.js, viewer.js
  EXPECT_EQ(count(html, "Copyright 2010-2024 Three.js Authors"), 1u);
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos);
  EXPECT_EQ(count(html, "root.stride_fk_lib = api;"), 1u);
  EXPECT_EQ(count(html, "window.stride_fk = "), 1u);
  // each script ends where its element ends: one </script> per <script
  EXPECT_EQ(count(html, "<script"), count(html, "</script>"));
  EXPECT_EQ(count(html, "</script>"), 4u);
}

TEST(viewer_page, the_fk_script_is_the_one_the_page_holds) {
  const std::string html = render_page("t", "{}");
  EXPECT_NE(html.find(std::string(fk_script())), std::string::npos);
  EXPECT_GT(fk_script().size(), 1000u);
}

}  // namespace
}  // namespace stride::viewer
