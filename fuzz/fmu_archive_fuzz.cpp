// FMU archive extraction (libstride): arbitrary bytes as a .fmu, extracted with the importer's
// limits into a private folder. Whatever it extracts must stay inside that folder.
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "fuzz_input.hpp"
#include "stride/cosim/archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const stride::fuzz::input_file archive(data, size, "fuzz.fmu");
  const auto destination = archive.dir() / "x";
  std::filesystem::create_directory(destination);
  // small limits: a fuzzer-made bomb must be stopped, not written out
  stride::cosim::extract_limits limits;
  limits.max_entry_size = limits.max_total_size = 1 << 20;
  limits.max_entries = 1000;
  try {
    stride::cosim::extract_archive(archive.path(), destination, limits);
  } catch (const std::exception&) {
  }
  // nothing may appear beside the archive and the destination
  for (const auto& entry : std::filesystem::directory_iterator(archive.dir())) {
    if (entry.path() != archive.path() && entry.path() != destination) std::abort();
  }
  return 0;
}
