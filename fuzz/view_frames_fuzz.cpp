// The run viewer's reader of recorded frames (viewer/src/recorded_frames.cpp) on arbitrary CSV
// bytes: the header, the pose prefixes, the frames of the first prefix (with an episode column
// when there is one, decimated and thinned) and the span of one episode value.
#include <exception>
#include <string>

#include "fuzz_input.hpp"
#include "recorded_frames.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const stride::fuzz::input_file file(data, size, "view.csv");
  try {
    namespace viewer = stride::viewer;
    const auto columns = viewer::csv_header(file.path());
    const auto prefixes = viewer::full_pose_prefixes(columns);
    const std::string prefix = prefixes.empty() ? "r" : prefixes.front();
    viewer::frame_selection s;
    s.fps = size % 3 == 0 ? 0 : 10;
    for (const auto& c : columns) {
      if (c.ends_with(".episode")) s.span_column = c;
    }
    viewer::recorded_frames f = viewer::read_frames(file.path(), prefix, {1, 3}, {}, s);
    viewer::thin_frames(f, 2);
    if (!s.span_column.empty()) (void)viewer::find_span(file.path(), s.span_column, 1);
  } catch (const std::exception&) {
  }
  return 0;
}
