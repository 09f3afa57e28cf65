// Registers a component as the one model of an FMU. In exactly one .cpp of the component:
//
//   STRIDE_FMU(my_model)
//
// where my_model has
//   static stride::sdk::model_info info();
//   static stride::sdk::variable_table variables();    // built once with table_builder<data>
//   explicit my_model(const stride::sdk::instance_context&);
// The shared glue (FMI functions) and the modelDescription generator both use this definition.
#pragma once

#include <memory>

#include "stride/sdk/model.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

struct fmu_definition {
  model_info info;
  variable_table table;
  std::unique_ptr<model> (*create)(const instance_context&);
};

namespace detail {
/// Defined by STRIDE_FMU in the component.
const fmu_definition& registered_fmu();
}  // namespace detail

}  // namespace stride::sdk

#define STRIDE_FMU(model_type)                                                   \
  const ::stride::sdk::fmu_definition& ::stride::sdk::detail::registered_fmu() { \
    static const ::stride::sdk::fmu_definition definition{                       \
        model_type::info(), model_type::variables(),                             \
        [](const ::stride::sdk::instance_context& context)                       \
            -> std::unique_ptr<::stride::sdk::model> {                           \
          return std::make_unique<model_type>(context);                          \
        }};                                                                      \
    return definition;                                                           \
  }
