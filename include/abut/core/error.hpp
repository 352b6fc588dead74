#pragma once
// The two kinds of failure a user meets: bad input (exit code 2) and an unstable run (exit code 3).
#include <cstddef>
#include <stdexcept>
#include <string>

namespace abut {

// Where in the input something came from: file, 1-based line, keyword and field name.
struct SourceLocation {
  std::string file;
  std::size_t line = 0;
  std::string keyword;
  std::string field;
};

// An error the user can fix in the input. what() reads
//   "<file>:<line>: *KEYWORD, field 'name': <message>"
// with the parts that are known; the message says what is expected.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  InputError(const SourceLocation& where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// The run became unstable (NaN, inverted element, ...). The solver writes its last good state first.
class InstabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace abut
