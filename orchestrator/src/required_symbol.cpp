#include "required_symbol.hpp"

#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

void* required_symbol(void* address, const char* name, const std::string& binary) {
  if (address == nullptr) throw fmu_import_error(binary + " does not export " + name);
  return address;
}

}  // namespace stride::cosim::detail
