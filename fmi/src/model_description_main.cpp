// Build-time generator: writes the modelDescription.xml of the component it is linked with.
// Usage: <component>_model_description [--fmi3] OUTPUT.xml [RESOURCE_DIR]
// --fmi3: FMI 3.0 instead of 2.0.
// RESOURCE_DIR: the resources/ folder of the FMU, for a component that reads its interface from
// there (STRIDE_FMU_FROM_RESOURCES).
// The generation time honours SOURCE_DATE_EPOCH for reproducible builds.
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>
#include <string_view>

#include "stride/sdk/model_description.hpp"

int main(int argc, char** argv) {
  const char* program = argv[0];
  const bool fmi3 = argc > 1 && std::string_view(argv[1]) == "--fmi3";
  if (fmi3) {
    --argc;
    ++argv;
  }
  if (argc != 2 && argc != 3) {
    std::cerr << "usage: " << program << " [--fmi3] OUTPUT.xml [RESOURCE_DIR]\n";
    return 2;
  }
  try {
    std::time_t now = std::time(nullptr);
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"))
      now = std::strtoll(epoch, nullptr, 10);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    const auto fmu = stride::sdk::detail::fmu_for(argc == 3 ? argv[2] : "");
    const std::string xml = fmi3 ? stride::sdk::write_model_description3(*fmu, stamp)
                                 : stride::sdk::write_model_description(*fmu, stamp);
    std::ofstream out(argv[1], std::ios::binary);
    out << xml;
    if (!out) {
      std::cerr << program << ": cannot write " << argv[1] << '\n';
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << '\n';
    return 1;
  }
  return 0;
}
