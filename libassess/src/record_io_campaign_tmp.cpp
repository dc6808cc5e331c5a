// record_io_campaign_tmp.cpp: TEMPORARY PEER AT2 reader (see record_io.hpp).
#include "assess/record_io.hpp"

#include "assess/error.hpp"
#include "assess/units.hpp"

#include <fstream>
#include <regex>
#include <sstream>

namespace assess {

Record read_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open record file '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  for (char& c : text)
    if (c == '\r') c = '\n';
  std::istringstream is(text);
  std::string line;
  std::vector<std::string> header;
  while (header.size() < 4 && std::getline(is, line))
    if (!line.empty()) header.push_back(line);
  if (header.size() < 4) throw InputError("record file '" + path + "': header shorter than 4 lines");
  std::smatch m;
  const std::regex rn("NPTS\\s*=\\s*(\\d+)", std::regex::icase), rd("DT\\s*=\\s*([0-9.eE+-]+)", std::regex::icase);
  if (!std::regex_search(header[3], m, rn)) throw InputError("record file '" + path + "': no NPTS");
  const std::size_t n = std::stoul(m[1]);
  if (!std::regex_search(header[3], m, rd)) throw InputError("record file '" + path + "': no DT");
  Record r;
  r.dt = std::stod(m[1]);
  if (!(r.dt > 0.0)) throw InputError("record file '" + path + "': DT must be > 0");
  std::string tok;
  while (r.acc.size() < n && is >> tok) {
    try {
      r.acc.push_back(std::stod(tok) * units::g_n);
    } catch (const std::exception&) {
      throw InputError("record file '" + path + "': non-numeric value '" + tok + "'");
    }
  }
  if (r.acc.size() != n)
    throw InputError("record file '" + path + "': " + std::to_string(r.acc.size()) + " values, header says " +
                     std::to_string(n));
  r.source = path;
  r.format = "PEER AT2";
  return r;
}

}  // namespace assess
