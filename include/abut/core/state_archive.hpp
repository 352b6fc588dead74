#pragma once
// The evolving state of a solver object as bytes, for restart files (issue 13). Each stateful
// class lists its state once, in a member `archive(StateArchive&)` that both saves and loads:
// calling it on an archive for saving appends the values, on one for loading reads them back in
// the same order. A restart is bitwise identical to the uninterrupted run only when every value
// that the next cycle reads is listed; the restart tests compare whole runs to catch an omission.
//
// Values are stored in the machine's own representation (a restart file is read on the machine
// type that wrote it); marks between the sections turn a file from another model or version into
// a clear error instead of garbage.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace abut {

// A restart file that does not fit the model or is damaged.
class StateArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  static StateArchive for_saving() { return StateArchive(true, {}); }
  static StateArchive for_loading(std::vector<char> bytes) {
    return StateArchive(false, std::move(bytes));
  }

  bool saving() const { return saving_; }
  const std::vector<char>& bytes() const { return bytes_; }
  // Loading: every byte was read (a longer file came from another model).
  bool exhausted() const { return read_ == bytes_.size(); }

  // A plain value, or an object that lists its own state (a member archive(StateArchive&)).
  template <class T>
  void value(T& v) {
    if constexpr (requires { v.archive(*this); }) {
      v.archive(*this);
    } else {
      static_assert(std::is_trivially_copyable_v<T>, "archive plain values only");
      raw(&v, sizeof(T));
    }
  }
  void value(std::string& s) {
    std::uint64_t n = s.size();
    value(n);
    if (!saving_) s.resize(checked_count(n, 1));
    raw(s.data(), s.size());
  }
  template <class T>
  void value(std::vector<T>& v) {
    std::uint64_t n = v.size();
    value(n);
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (!saving_) v.resize(checked_count(n, sizeof(T)));
      raw(v.data(), v.size() * sizeof(T));
    } else {  // objects: as many as the model made
      if (!saving_ && n != v.size())
        fail("expected " + std::to_string(v.size()) + " items, found " + std::to_string(n));
      for (T& item : v) value(item);
    }
  }
  template <class T>
  void value(std::optional<T>& v) {
    bool present = v.has_value();
    value(present);
    if (!saving_ && present != v.has_value())
      fail("a part of the state is present in one and absent in the other");
    if (v) value(*v);
  }
  template <class... T>
  void values(T&... v) {
    (value(v), ...);
  }
  // As values(), for arrays whose length the model fixes (one value per node, element or
  // point): loading checks that the file's length is the model's, so that a deck changed in a
  // way that changes the state's layout (a material with other history, another contact
  // discretisation) is refused, not read into arrays of the wrong length.
  template <class... T>
  void fixed(T&... v) {
    (fixed_one(v), ...);
  }

  // A named boundary between sections: saving writes the name, loading checks it.
  void mark(std::string_view name) {
    std::string found(name);
    value(found);
    if (!saving_ && found != name)
      fail("expected the section '" + std::string(name) + "', found '" + found.substr(0, 40) + "'");
  }
  // Loading: a value the model fixes (a count) must be what the file holds.
  template <class T>
  void expect(T v, std::string_view what) {
    T stored = v;
    value(stored);
    if (!saving_ && std::memcmp(&stored, &v, sizeof(T)) != 0)
      fail(std::string(what) + " differs from the model's");
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw StateArchiveError(why + " (at byte " + std::to_string(read_) + ")");
  }

 private:
  template <class T>
  void fixed_one(std::vector<T>& v) {
    if (!saving_) {
      std::uint64_t n = 0;
      std::memcpy(&n, bytes_.data() + read_, std::min(sizeof n, bytes_.size() - read_));
      if (bytes_.size() - read_ >= sizeof n && n != v.size())
        fail("an array of " + std::to_string(v.size()) + " values holds " + std::to_string(n) +
             " in the file");
    }
    value(v);
  }
  template <class T>
  void fixed_one(T& v) {
    value(v);
  }

  StateArchive(bool saving, std::vector<char> bytes) : saving_(saving), bytes_(std::move(bytes)) {}

  void raw(void* data, std::size_t size) {
    if (size == 0) return;
    if (saving_) {
      const char* p = static_cast<const char*>(data);
      bytes_.insert(bytes_.end(), p, p + size);
      return;
    }
    if (bytes_.size() - read_ < size) fail("the file ends early");
    std::memcpy(data, bytes_.data() + read_, size);
    read_ += size;
  }
  // A count read from the file, bounded by the bytes left, so a damaged file cannot ask for an
  // enormous allocation.
  std::size_t checked_count(std::uint64_t n, std::size_t item_size) const {
    if (item_size > 0 && n > (bytes_.size() - read_) / item_size) fail("a count exceeds the file");
    return static_cast<std::size_t>(n);
  }

  bool saving_;
  std::vector<char> bytes_;
  std::size_t read_ = 0;
};

}  // namespace abut
