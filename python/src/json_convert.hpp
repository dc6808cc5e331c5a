// json_convert.hpp: Python values to and from nlohmann::json for the module
// assess (python/src/module.cpp): a case, a site or a campaign given as a
// dict becomes the JSON document the library parses; the JSON documents the
// library builds (the command line's --json) become dicts and lists.
#pragma once

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>

namespace assess::python {

/// A Python value as JSON: None, bool, int, float, str, a mapping with str
/// keys, a list or tuple, a numpy scalar or array (its tolist()), an
/// os.PathLike (its path). Anything else, a key that is not a string, an int
/// beyond 64 bits or a nesting deeper than json_max_depth (a dict that holds
/// itself) is an InputError naming `file` and the JSON path.
nlohmann::json to_json(pybind11::handle value, const std::string& file);

/// JSON as Python: objects as dicts (keys in the document's order), arrays
/// as lists; a number that is not finite as None, as the command line's
/// JSON prints it (null).
pybind11::object to_python(const nlohmann::json& j);
pybind11::object to_python(const nlohmann::ordered_json& j);

}  // namespace assess::python
