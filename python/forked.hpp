// python/forked.hpp -- a computation in a forked child process (core.cpp's header comment says
// when the binding still uses one): the parent waits with the GIL released, Ctrl-C kills the
// child and raises KeyboardInterrupt, a crash in the child cannot take the interpreter down.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>

namespace hapstab::python {

/// Runs `work` in a forked child and returns what it returned (passed through the pipe as
/// JSON). An InputError / NumericalError thrown in the child is thrown again here.
nlohmann::json run_forked(const std::function<nlohmann::json()>& work);

}  // namespace hapstab::python
