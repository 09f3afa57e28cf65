// The learner's checkpoint reader on an arbitrary file (what --resume reads).
#include <exception>

#include "fuzz_input.hpp"
#include "stride/learner/artefacts.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const stride::fuzz::input_file file(data, size, "checkpoint.bin");
  try {
    (void)stride::learner::read_checkpoint(file.path());
  } catch (const std::exception&) {
  }
  return 0;
}
