#include "stride/sdk/variable_table.hpp"

#include <stdexcept>

namespace stride::sdk {

variable_table::variable_table(std::vector<variable> vars, std::shared_ptr<const void> defaults,
                               std::size_t data_size)
    : vars_(std::move(vars)), defaults_(std::move(defaults)), data_size_(data_size) {
  for (const variable& v : vars_) {
    if (v.value_reference >= by_vr_.size()) by_vr_.resize(v.value_reference + 1, nullptr);
    by_vr_[v.value_reference] = &v;
  }
}

const variable* variable_table::find(std::string_view name) const {
  for (const variable& v : vars_) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

template <class F>
variable_group& variable_group::each(F f) {
  for (std::size_t i = first_; i < first_ + count_; ++i) f(builder_->vars_[i]);
  return *this;
}

variable_group& variable_group::parameter() {
  return each([](variable& v) {
    v.causality_kind = causality::parameter;
    v.variability_kind = variability::fixed;
    v.initial = initial_kind::exact;
  });
}

variable_group& variable_group::tunable() {
  return each([](variable& v) { v.variability_kind = variability::tunable; });
}

variable_group& variable_group::calculated_parameter() {
  return each([](variable& v) {
    v.causality_kind = causality::calculated_parameter;
    v.variability_kind = variability::fixed;
    v.initial = initial_kind::calculated;
  });
}

variable_group& variable_group::input() {
  return each([](variable& v) {
    v.causality_kind = causality::input;
    v.variability_kind =
        v.type == value_type::real ? variability::continuous : variability::discrete;
    v.initial = initial_kind::none;
  });
}

variable_group& variable_group::output() {
  return each([](variable& v) {
    v.causality_kind = causality::output;
    v.variability_kind =
        v.type == value_type::real ? variability::continuous : variability::discrete;
    v.initial = initial_kind::calculated;
  });
}

variable_group& variable_group::local() {
  return each([](variable& v) {
    v.causality_kind = causality::local;
    v.variability_kind =
        v.type == value_type::real ? variability::continuous : variability::discrete;
    v.initial = initial_kind::calculated;
  });
}

variable_group& variable_group::discrete() {
  return each([](variable& v) { v.variability_kind = variability::discrete; });
}

variable_group& variable_group::unit(std::string u) {
  return each([&](variable& v) { v.unit = u; });
}

variable_group& variable_group::describe(std::string d) {
  return each([&](variable& v) { v.description = d; });
}

variable_group& variable_group::min(double value) {
  return each([&](variable& v) {
    v.min = value;
    v.has_min = true;
  });
}

variable_group& variable_group::max(double value) {
  return each([&](variable& v) {
    v.max = value;
    v.has_max = true;
  });
}

variable_group& variable_group::check(std::function<void(double)> f) {
  return each([&](variable& v) { v.check = f; });
}

variable_group& variable_group::depends_on(std::vector<std::string> input_names) {
  for (std::size_t i = first_; i < first_ + count_; ++i) {
    builder_->pending_dependencies_.emplace_back(i, input_names);
  }
  return *this;
}

variable_group table_builder_base::add(std::string name, value_type type, std::size_t offset,
                                       std::size_t count, std::size_t stride,
                                       std::size_t string_capacity, bool is_array) {
  const std::size_t first = vars_.size();
  for (std::size_t i = 0; i < count; ++i) {
    variable v;
    v.name = is_array ? name + "[" + std::to_string(i + 1) + "]" : name;
    v.value_reference = static_cast<std::uint32_t>(vars_.size());
    v.type = type;
    v.offset = offset + i * stride;
    v.string_capacity = string_capacity;
    if (is_array) {
      v.array_index = i + 1;
      v.array_size = count;
    }
    vars_.push_back(std::move(v));
  }
  return variable_group(*this, first, count);
}

variable_table table_builder_base::finish(std::shared_ptr<const void> defaults,
                                          std::size_t data_size) {
  for (auto& [index, names] : pending_dependencies_) {
    for (const std::string& name : names) {
      const variable* input = nullptr;
      for (const variable& v : vars_) {
        if (v.name == name) input = &v;
      }
      if (input == nullptr || input->causality_kind != causality::input) {
        throw std::logic_error("variable '" + vars_[index].name + "' depends on '" + name +
                               "', which is not an input");
      }
      vars_[index].direct_dependencies.push_back(input->value_reference);
    }
  }
  for (const variable& v : vars_) {
    if (v.type != value_type::real && v.variability_kind == variability::continuous) {
      throw std::logic_error("variable '" + v.name + "': only Real variables can be continuous");
    }
  }
  return variable_table(std::move(vars_), std::move(defaults), data_size);
}

variable_table buffer_table_builder::finish() {
  auto bytes = std::make_shared<std::vector<std::byte>>(std::move(defaults_));
  const std::size_t size = bytes->size();
  const void* start = bytes->data();
  variable_table table =
      table_builder_base::finish(std::shared_ptr<const void>(std::move(bytes), start), size);
  table.storage_ = std::move(storage_);
  return table;
}

}  // namespace stride::sdk
