// The FMU checker (stride-fmu-check, `stride validate`) on arbitrary bytes: input that starts
// like a ZIP file is checked as a whole .fmu (archive rules, then its modelDescription.xml),
// anything else as the text of a modelDescription.xml. Unlike the importers the checker reports
// every defect as a finding, so any exception is a bug here.
#include <string_view>

#include "fuzz_input.hpp"
#include "stride/fmi_check/fmu_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = stride::fuzz::as_text(data, size);
  if (text.starts_with("PK")) {
    const stride::fuzz::input_file fmu(data, size, "fuzz.fmu");
    (void)stride::fmi_check::check_fmu(fmu.path());
  } else {
    const stride::fmi_check::archive_listing archive{"modelDescription.xml",
                                                     "binaries/linux64/x.so"};
    (void)stride::fmi_check::check_model_description(text, &archive);
  }
  return 0;
}
