// error.hpp: the one exception type of libassess.
//
// Invalid input (a value out of range, a malformed file, an inconsistent
// model) throws InputError with a message that names the field or option,
// what was expected and its unit. Physical outcomes (overturning, a mechanism
// that never activates) are results, never exceptions; numerical failures of
// the integrator are a Termination value in the result.
//
// A failure of the machine rather than of the input (a full disk, an I/O
// error, memory exhausted while writing an output) throws SystemError, with a
// message that names the file and the system's reason; the CLI exits with
// status 1 for it, 2 for an InputError (docs/reliability.md).
#pragma once

#include <stdexcept>
#include <string>

namespace assess {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

class SystemError : public std::runtime_error {
 public:
  explicit SystemError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace assess
