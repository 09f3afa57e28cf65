// The HTML page: viewer/web/viewer.html with three.js, fk.js, viewer.js and the data inlined
// (all embedded into the program at build time, so nothing is fetched when a page is written
// or viewed).
#ifndef STRIDE_VIEWER_PAGE_HPP
#define STRIDE_VIEWER_PAGE_HPP

#include <string>
#include <string_view>

namespace stride::viewer {

/// The page for `data_json` (page_json) with `title`.
std::string render_page(std::string_view title, std::string_view data_json);

/// The embedded fk.js (tests evaluate it with node).
std::string_view fk_script();

}  // namespace stride::viewer

#endif  // STRIDE_VIEWER_PAGE_HPP
