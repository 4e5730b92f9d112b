// The .pvd collection, written by hand: VTK 9.1 has no writer for it, and the
// format is a few lines of XML that ParaView reads as a time series.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"

namespace rockfdem::coupling {
namespace {

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// %.17g round-trips every double exactly, so the time in ParaView is the
// simulated time, not a rounded copy.
std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string dataset_line(const PvdEntry& e, std::size_t index) {
  if (e.file.empty()) {
    throw std::invalid_argument("pvd entry " + std::to_string(index) + ": empty file name");
  }
  if (!std::isfinite(e.time)) {
    throw std::invalid_argument("pvd entry " + std::to_string(index) + " ('" + e.file +
                                "'): time is not finite");
  }
  return "    <DataSet timestep=\"" + exact(e.time) + "\" group=\"\" part=\"0\" file=\"" +
         xml_escaped(e.file) + "\"/>\n";
}

}  // namespace

void write_pvd(const std::vector<PvdEntry>& entries, const std::string& path) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (std::size_t i = 0; i < entries.size(); ++i) xml += dataset_line(entries[i], i);
  xml +=
      "  </Collection>\n"
      "</VTKFile>\n";
  atomic_write_text(path, xml);
}

}  // namespace rockfdem::coupling
