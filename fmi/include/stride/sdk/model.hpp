// What a component implements. A component is a plain C++ core plus a `model` that owns the
// variable values (a trivially copyable data struct) and advances them in do_step. The shared
// FMI glue drives it; components never see FMI types.
//
// Lifecycle, as the glue calls it:
//   construct (fmi2Instantiate)  → sets of start values / parameters →
//   enter_initialization → sets → exit_initialization → { sets → do_step → gets }… →
//   terminate → destroy (fmi2FreeInstance).  fmi2Reset destroys and constructs again.
// calculate_values() is called before a get whenever a set happened since the last
// computation, so outputs with direct feedthrough are always current.
#pragma once

#include <cstddef>
#include <cstring>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/sdk/types.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

/// Thrown by a component for any failure; the glue reports the message through the FMI logger
/// and returns fmi2Error.
class model_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class log_level { info, warning, error };

/// Sends messages through the importer's FMI logger callback. Debug categories are filtered by
/// fmi2SetDebugLogging; warnings and errors always go out.
class logger {
 public:
  virtual ~logger() = default;
  virtual bool enabled(const char* category) const = 0;
  virtual void log(log_level level, const char* category, const std::string& message) = 0;

  void info(const char* category, const std::string& message) {
    if (enabled(category)) log(log_level::info, category, message);
  }
  void warning(const std::string& message) { log(log_level::warning, "logStatusWarning", message); }
  void error(const std::string& message) { log(log_level::error, "logStatusError", message); }
};

/// Everything an instance knows about where it runs.
struct instance_context {
  std::string instance_name;
  std::string resource_dir;  // local path of the unpacked resources/ folder ("" if none given)
  logger* log = nullptr;
};

/// Result of one do_step.
enum class step_result {
  ok,
  terminate,  // the component asks to end the run here (fmi2Discard + fmi2Terminated)
};

/// Static facts about a component, written into modelDescription.xml.
struct model_info {
  std::string model_name;
  std::string model_identifier;
  std::string description;
  std::string author = "Stride";
  std::string version = "0.1.0";
  double default_step_size = 0.01;  // DefaultExperiment stepSize [s]
  double default_stop_time = 0.0;   // 0: none written
  /// Component-specific debug log categories, besides the standard ones.
  std::vector<std::pair<std::string, std::string>> log_categories;
};

/// Base of every component instance.
class model {
 public:
  virtual ~model() = default;

  /// Base address of the data struct the variable table's offsets refer to.
  virtual void* data() = 0;

  virtual void enter_initialization() {}
  /// Computes the initial outputs from parameters and inputs.
  virtual void exit_initialization() { calculate_values(); }
  /// Advances from t to t + h; both in integer nanoseconds.
  virtual step_result do_step(time_ns t, time_ns h) = 0;
  /// Brings feedthrough outputs up to date after sets.
  virtual void calculate_values() {}
  /// Called after a successful set of `v` (e.g. to note which parameters were given).
  virtual void on_set(const variable& v) { (void)v; }
  virtual void terminate() {}

  /// The complete evolving state as bytes; restoring it must reproduce the continuation
  /// bit-exactly.
  virtual std::vector<std::byte> save_state() const = 0;
  /// Throws model_error when the bytes do not fit this component.
  virtual void restore_state(std::span<const std::byte> bytes) = 0;
};

/// A model whose whole state is its trivially copyable `Data`: state save/restore are copies.
template <class Data>
class model_base : public model {
 public:
  void* data() override { return &data_; }

  std::vector<std::byte> save_state() const override {
    std::vector<std::byte> bytes(sizeof(Data));
    std::memcpy(bytes.data(), &data_, sizeof(Data));
    return bytes;
  }
  void restore_state(std::span<const std::byte> bytes) override {
    if (bytes.size() != sizeof(Data)) {
      throw model_error("FMU state has " + std::to_string(bytes.size()) + " bytes, expected " +
                        std::to_string(sizeof(Data)));
    }
    std::memcpy(&data_, bytes.data(), sizeof(Data));
  }

 protected:
  Data data_{};
};

/// A model whose values live in a byte buffer laid out by buffer_table_builder (a component
/// whose interface is read at run time); the buffer starts as the table's start values and is
/// the whole state unless the model adds its own.
class buffer_model : public model {
 public:
  explicit buffer_model(const variable_table& table)
      : data_(static_cast<const std::byte*>(table.defaults()),
              static_cast<const std::byte*>(table.defaults()) + table.data_size()) {}
  void* data() override { return data_.data(); }

  std::vector<std::byte> save_state() const override { return data_; }
  void restore_state(std::span<const std::byte> bytes) override {
    if (bytes.size() != data_.size()) {
      throw model_error("FMU state has " + std::to_string(bytes.size()) + " bytes, expected " +
                        std::to_string(data_.size()));
    }
    std::memcpy(data_.data(), bytes.data(), bytes.size());
  }

 protected:
  /// The value of T at `offset` (as reserved with buffer_table_builder).
  template <class T>
  T& value(std::size_t offset) {
    return *std::launder(reinterpret_cast<T*>(data_.data() + offset));
  }
  template <class T>
  const T& value(std::size_t offset) const {
    return *std::launder(reinterpret_cast<const T*>(data_.data() + offset));
  }
  std::size_t data_size() const { return data_.size(); }

 private:
  std::vector<std::byte> data_;
};

}  // namespace stride::sdk
