// json_convert.cpp: Python values to and from nlohmann::json (json_convert.hpp).
#include "json_convert.hpp"

#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>

#include <cmath>
#include <string>

namespace py = pybind11;

namespace assess::python {
namespace {

std::string type_name(py::handle v) { return py::str(py::type::handle_of(v).attr("__name__")); }

nlohmann::json convert(py::handle v, const std::string& file, const std::string& path, std::size_t depth) {
  auto fail = [&](const std::string& what) -> nlohmann::json {
    throw InputError(file + ": " + (path.empty() ? std::string("/") : path) + ": " + what);
  };
  if (depth > json_max_depth)
    fail("nested more than " + std::to_string(json_max_depth) + " levels (a dict or list that holds itself?)");
  if (v.is_none()) return nullptr;
  if (PyBool_Check(v.ptr())) return v.ptr() == Py_True;
  if (PyLong_Check(v.ptr())) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    // As nlohmann's parser reads JSON text: a non-negative integer unsigned, a negative one signed.
    if (overflow == 0) return i >= 0 ? nlohmann::json(static_cast<std::uint64_t>(i)) : nlohmann::json(static_cast<std::int64_t>(i));
    if (overflow > 0) {
      const unsigned long long u = PyLong_AsUnsignedLongLong(v.ptr());
      if (!PyErr_Occurred()) return static_cast<std::uint64_t>(u);
      PyErr_Clear();
    }
    return fail("the integer " + std::string(py::str(v)) + " is beyond 64 bits");
  }
  if (PyFloat_Check(v.ptr())) return PyFloat_AS_DOUBLE(v.ptr());
  if (PyUnicode_Check(v.ptr())) return v.cast<std::string>();
  if (PyDict_Check(v.ptr())) {
    nlohmann::json o = nlohmann::json::object();
    for (auto item : py::reinterpret_borrow<py::dict>(v)) {
      if (!PyUnicode_Check(item.first.ptr()))
        fail("the key " + std::string(py::repr(item.first)) + " is not a string (JSON keys are strings)");
      const std::string key = item.first.cast<std::string>();
      o[key] = convert(item.second, file, path + "/" + key, depth + 1);
    }
    return o;
  }
  if (PyList_Check(v.ptr()) || PyTuple_Check(v.ptr())) {
    nlohmann::json a = nlohmann::json::array();
    std::size_t i = 0;
    for (py::handle e : v) a.push_back(convert(e, file, path + "/" + std::to_string(i++), depth + 1));
    return a;
  }
  // numpy scalars and arrays: their Python value (tolist() of a 0-d or n-d array, item() of a scalar).
  if (py::hasattr(v, "dtype") && py::hasattr(v, "tolist")) return convert(v.attr("tolist")(), file, path, depth + 1);
  // pathlib.Path and any os.PathLike: the path.
  if (py::hasattr(v, "__fspath__")) return convert(v.attr("__fspath__")(), file, path, depth + 1);
  // Other mappings and sequences (collections.abc).
  const py::module_ abc = py::module_::import("collections.abc");
  if (py::isinstance(v, abc.attr("Mapping"))) return convert(py::dict(py::reinterpret_borrow<py::object>(v)), file, path, depth);
  if (py::isinstance(v, abc.attr("Sequence")) && !PyBytes_Check(v.ptr()))
    return convert(py::list(py::reinterpret_borrow<py::object>(v)), file, path, depth);
  return fail("a value of Python type " + type_name(v) + " (expected a JSON value: None, bool, int, float, str, "
              "list or dict)");
}

template <class J>
py::object back(const J& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(j.template get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.template get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.template get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      const double d = j.template get<double>();
      return std::isfinite(d) ? py::object(py::float_(d)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string: return py::str(j.template get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list l(j.size());
      std::size_t i = 0;
      for (const auto& e : j) l[i++] = back(e);
      return std::move(l);
    }
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = back(it.value());
      return std::move(d);
    }
    default: return py::none();  // binary and discarded: never built by the library
  }
}

}  // namespace

nlohmann::json to_json(py::handle value, const std::string& file) { return convert(value, file, "", 0); }

py::object to_python(const nlohmann::json& j) { return back(j); }
py::object to_python(const nlohmann::ordered_json& j) { return back(j); }

}  // namespace assess::python
