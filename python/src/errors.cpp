// echoplan.InputError: what the C++ code throws for bad input (common/error.h), as a Python
// exception that keeps the file, the line and the problem apart, so a caller can point at them.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "bindings.h"
#include "common/error.h"

namespace echoplan::python {

void bind_errors(py::module_& m) {
  // A subclass of ValueError: bad input is a bad value, and `except ValueError` catches it. The
  // type lives as long as the interpreter (the translator below needs it at any time).
  static py::handle input_error =
      py::exception<InputError>(m, "InputError", PyExc_ValueError).release();
  input_error.attr("__doc__") =
      "Bad input: a file, a value, a recording. str(e) is 'file:line: problem'; e.file (may be "
      "empty), e.line (1-based, 0 when the problem is about a whole file or has no line) and "
      "e.problem hold the parts.";
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      py::gil_scoped_acquire gil;
      py::object error = input_error(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("problem") = e.problem();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace echoplan::python
