// Registers a component as the one model of an FMU. In exactly one .cpp of the component:
//
//   STRIDE_FMU(my_model)
//
// where my_model has
//   static stride::sdk::model_info info();
//   static stride::sdk::variable_table variables();    // built once with table_builder<data>
//   explicit my_model(const stride::sdk::instance_context&);
// The shared glue (FMI functions) and the modelDescription generator both use this definition.
//
// A component whose interface is only known from files in its resources/ folder (a generated
// FMU) registers a loader instead:
//
//   STRIDE_FMU_FROM_RESOURCES(load_my_fmu)
//
// with `std::shared_ptr<const stride::sdk::fmu_definition> load_my_fmu(const std::string&
// resource_dir)`. The glue calls it in fmi2Instantiate with the unpacked resources folder (once
// per folder) and the generator with the folder given on its command line.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "stride/sdk/model.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

struct fmu_definition {
  model_info info;
  variable_table table;
  std::function<std::unique_ptr<model>(const instance_context&)> create;
};

namespace detail {
/// Defined by STRIDE_FMU in the component.
const fmu_definition& registered_fmu();
/// Defined by STRIDE_FMU and STRIDE_FMU_FROM_RESOURCES: the definition for the FMU unpacked with
/// this resources folder. \throws model_error when the resources do not define an FMU.
std::shared_ptr<const fmu_definition> fmu_for(const std::string& resource_dir);
}  // namespace detail

}  // namespace stride::sdk

#define STRIDE_FMU(model_type)                                                       \
  const ::stride::sdk::fmu_definition& ::stride::sdk::detail::registered_fmu() {     \
    static const ::stride::sdk::fmu_definition definition{                           \
        model_type::info(), model_type::variables(),                                 \
        [](const ::stride::sdk::instance_context& context)                           \
            -> std::unique_ptr<::stride::sdk::model> {                               \
          return std::make_unique<model_type>(context);                              \
        }};                                                                          \
    return definition;                                                               \
  }                                                                                  \
  std::shared_ptr<const ::stride::sdk::fmu_definition> stride::sdk::detail::fmu_for( \
      const std::string&) {                                                          \
    return {std::shared_ptr<void>(), &registered_fmu()};                             \
  }

#define STRIDE_FMU_FROM_RESOURCES(loader)                                            \
  std::shared_ptr<const ::stride::sdk::fmu_definition> stride::sdk::detail::fmu_for( \
      const std::string& resource_dir) {                                             \
    return loader(resource_dir);                                                     \
  }
