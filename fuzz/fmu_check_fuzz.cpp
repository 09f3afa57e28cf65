// The FMU checker (stride-fmu-check, `stride validate`) on arbitrary modelDescription.xml bytes.
// Unlike the importers it reports every defect as a finding, so any exception is a bug here.
#include "fuzz_input.hpp"
#include "stride/fmi_check/fmu_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const stride::fmi_check::archive_listing archive{"modelDescription.xml",
                                                   "binaries/linux64/x.so"};
  (void)stride::fmi_check::check_model_description(stride::fuzz::as_text(data, size), &archive);
  return 0;
}
