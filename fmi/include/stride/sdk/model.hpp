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

#include "stride/common/bytes.hpp"
#include "stride/sdk/state_fields.hpp"
#include "stride/sdk/types.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

/// Thrown by a component for any failure; the glue reports the message through the FMI logger
/// and returns fmi2Error.
class model_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a state image; a damaged one (too short, too long, a Boolean neither 0 nor 1) is a
/// model_error.
class state_reader : public common::byte_reader<model_error> {
 public:
  explicit state_reader(std::span<const std::byte> bytes)
      : common::byte_reader<model_error>(bytes,
                                         "the FMU state is damaged or is not of this "
                                         "component (it ends early)") {}
  void require_end() const {
    if (!at_end()) throw model_error("the FMU state is longer than this component's state");
  }
};

/// The image of one described struct alone (stride/sdk/state_fields.hpp).
template <described_state T>
std::vector<std::byte> state_image(const T& s) {
  common::byte_writer w;
  put_state(w, s);
  return w.take();
}

/// Reads an image that is exactly one T into `s`: all of it or, when the image is damaged,
/// nothing. `s` is assigned, not replaced, so that addresses into it stay valid.
template <described_state T>
void read_state_image(std::span<const std::byte> bytes, T& s) {
  state_reader r(bytes);
  T restored = s;
  get_state(r, restored);
  r.require_end();
  s = restored;
}

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
  /// bit-exactly, on this host or any other (numbers little-endian, no padding: see
  /// stride/sdk/state_fields.hpp).
  virtual std::vector<std::byte> save_state() const = 0;
  /// Throws model_error when the bytes do not fit this component.
  virtual void restore_state(std::span<const std::byte> bytes) = 0;
};

/// A model whose whole state is its trivially copyable `Data`, whose fields `state_fields`
/// lists (stride/sdk/state_fields.hpp): its state image is those fields, portable across hosts.
template <class Data>
class model_base : public model {
  static_assert(described_state<Data>,
                "list the fields of the component's data struct in a state_fields() function "
                "beside it (stride/sdk/state_fields.hpp)");

 public:
  model_base() { require_complete_state_fields(); }

  void* data() override { return &data_; }

  std::vector<std::byte> save_state() const override { return state_image(data_); }
  // in place: the glue holds the data's address
  void restore_state(std::span<const std::byte> bytes) override { read_state_image(bytes, data_); }

 protected:
  Data data_{};

 private:
  // a member missing from state_fields() would be lost silently by every save and restore
  static void require_complete_state_fields() {
    static const std::string gap = state_fields_gap<Data>();
    if (!gap.empty()) {
      throw model_error("the component's state_fields() is incomplete: " + gap);
    }
  }
};

/// A model whose values live in a byte buffer laid out by buffer_table_builder (a component
/// whose interface is read at run time); the buffer starts as the table's start values and is
/// the whole state unless the model adds its own. Its image is every reserved value in order.
class buffer_model : public model {
 public:
  explicit buffer_model(const variable_table& table)
      : data_(static_cast<const std::byte*>(table.defaults()),
              static_cast<const std::byte*>(table.defaults()) + table.data_size()),
        storage_(table.storage()) {}
  void* data() override { return data_.data(); }

  std::vector<std::byte> save_state() const override {
    common::byte_writer w;
    save_buffer(w);
    return w.take();
  }
  void restore_state(std::span<const std::byte> bytes) override {
    state_reader r(bytes);
    const std::vector<std::byte> restored = read_buffer(r);
    r.require_end();
    set_buffer(restored);
  }

 protected:
  /// The buffer's part of an image that goes on with more.
  void save_buffer(common::byte_writer& w) const;
  /// Reads the buffer's part into the buffer: all of it or, when the image is damaged, nothing.
  void restore_buffer(state_reader& r) { set_buffer(read_buffer(r)); }

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
  std::vector<std::byte> read_buffer(state_reader& r) const;
  void set_buffer(const std::vector<std::byte>& values);

  std::vector<std::byte> data_;
  std::vector<storage_run> storage_;
};

}  // namespace stride::sdk
