#include "mpmx/io/vtk.hpp"

#include <bit>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::io::vtk {
namespace {

// Arrays are written in the machine's order and declared as such; VTK swaps on read.
constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
constexpr std::uint8_t kVtkVertex = 1;

// A name goes into an XML attribute.
std::string escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string unescape(std::string_view s) {
  static constexpr std::pair<std::string_view, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool matched = false;
    for (auto [entity, c] : kEntities) {
      if (s.substr(i, entity.size()) == entity) {
        out += c;
        i += entity.size();
        matched = true;
        break;
      }
    }
    if (!matched) out += s[i++];
  }
  return out;
}

// The raw appended section: each array is a UInt64 byte count followed by its bytes,
// and its DataArray tag carries its offset from the start of the section.
class Appended {
 public:
  // Queues `bytes` at `data` (the caller keeps them alive until write) and returns the
  // DataArray tag that points at them.
  std::string add(const char* type, const std::string& name_attr, int components, const void* data,
                  std::size_t bytes) {
    std::string tag = fmt::format(R"(<DataArray type="{}"{} NumberOfComponents="{}" )"
                                  R"(format="appended" offset="{}"/>)",
                                  type, name_attr, components, offset_);
    blocks_.push_back({data, bytes});
    offset_ += sizeof(std::uint64_t) + bytes;
    return tag;
  }
  void write(AtomicWriter& f) const {
    f.write("  <AppendedData encoding=\"raw\">\n   _");
    for (const auto& b : blocks_) {
      const std::uint64_t n = b.bytes;
      f.write(&n, sizeof n);
      f.write(b.data, b.bytes);
    }
    f.write("\n  </AppendedData>\n</VTKFile>\n");
  }

 private:
  struct Block {
    const void* data;
    std::size_t bytes;
  };
  std::vector<Block> blocks_;
  std::size_t offset_ = 0;
};

void check_fields(const std::string& path, const std::vector<Field>& fields, std::size_t n) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const Field& f = fields[i];
    if (f.name.empty() || f.components < 1)
      throw std::invalid_argument(
          fmt::format("VTK output {}: field {} needs a name and components >= 1", path, i));
    if (f.values.size() != n * static_cast<std::size_t>(f.components))
      throw std::invalid_argument(
          fmt::format("VTK output {}: field '{}' has {} values, expected {} points x {} components",
                      path, f.name, f.values.size(), n, f.components));
    for (std::size_t j = 0; j < i; ++j)
      if (fields[j].name == f.name)
        throw std::invalid_argument(
            fmt::format("VTK output {}: field '{}' given twice", path, f.name));
  }
}

// <PointData> naming the active attributes, so ParaView colours and glyphs by them
// and treats the 9-component array as a tensor.
std::string point_data(const std::vector<Field>& fields, Appended& data) {
  std::string attrs;
  auto active = [&](int components, const char* attr) {
    for (const Field& f : fields)
      if (f.components == components) {
        attrs += fmt::format(R"( {}="{}")", attr, escape(f.name));
        return;
      }
  };
  active(1, "Scalars");
  active(3, "Vectors");
  active(9, "Tensors");
  std::string xml = fmt::format("      <PointData{}>\n", attrs);
  for (const Field& f : fields) {
    xml += "        " +
           data.add("Float64", fmt::format(R"( Name="{}")", escape(f.name)), f.components,
                    f.values.data(), f.values.size() * sizeof(double)) +
           "\n";
  }
  return xml + "      </PointData>\n";
}

std::string file_head(const char* type) {
  return fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\">\n",
      type, kByteOrder);
}

}  // namespace

void write_points(const std::string& path, const std::vector<double>& xyz,
                  const std::vector<Field>& fields) {
  if (xyz.size() % 3 != 0)
    throw std::invalid_argument(
        fmt::format("VTK output {}: {} coordinates is not a multiple of 3", path, xyz.size()));
  const std::size_t n = xyz.size() / 3;
  check_fields(path, fields, n);

  // One VTK_VERTEX cell per point: readers and filters that work on cells see them.
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, kVtkVertex);

  Appended data;
  std::string xml = file_head("UnstructuredGrid");
  xml += "  <UnstructuredGrid>\n";
  xml += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n);
  xml += point_data(fields, data);
  xml += "      <Points>\n        " +
         data.add("Float64", R"( Name="Points")", 3, xyz.data(), xyz.size() * sizeof(double)) +
         "\n      </Points>\n";
  xml += "      <Cells>\n";
  xml += "        " +
         data.add("Int64", R"( Name="connectivity")", 1, connectivity.data(),
                  n * sizeof(std::int64_t)) +
         "\n";
  xml += "        " +
         data.add("Int64", R"( Name="offsets")", 1, offsets.data(), n * sizeof(std::int64_t)) +
         "\n";
  xml += "        " + data.add("UInt8", R"( Name="types")", 1, types.data(), n) + "\n";
  xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";

  AtomicWriter f(path);
  f.write(xml);
  data.write(f);
  f.commit();
}

void write_image(const std::string& path, std::array<int, 3> nodes, std::array<double, 3> origin,
                 std::array<double, 3> spacing, const std::vector<Field>& fields) {
  std::size_t n = 1;
  for (int d = 0; d < 3; ++d) {
    if (nodes[d] < 1)
      throw std::invalid_argument(
          fmt::format("VTK output {}: {} nodes along axis {}", path, nodes[d], d));
    n *= static_cast<std::size_t>(nodes[d]);
  }
  check_fields(path, fields, n);

  const std::string extent =
      fmt::format("0 {} 0 {} 0 {}", nodes[0] - 1, nodes[1] - 1, nodes[2] - 1);
  Appended data;
  std::string xml = file_head("ImageData");
  // "{}" prints the shortest text that reads back as the same double.
  xml += fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{} {} {}\" Spacing=\"{} {} {}\">\n",
                     extent, origin[0], origin[1], origin[2], spacing[0], spacing[1], spacing[2]);
  xml += fmt::format("    <Piece Extent=\"{}\">\n", extent);
  xml += point_data(fields, data);
  xml += "    </Piece>\n  </ImageData>\n";

  AtomicWriter f(path);
  f.write(xml);
  data.write(f);
  f.commit();
}

Series::Series(std::string path) : path_(std::move(path)) {}

void Series::add(double time, const std::string& file) {
  entries_.emplace_back(time, file);
  try {
    write();
  } catch (...) {
    entries_.pop_back();  // the list stays what the file on disk says
    throw;
  }
}

void Series::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"" +
      std::string(kByteOrder) + "\">\n  <Collection>\n";
  for (const auto& [time, file] : entries_)
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time,
                       escape(file));
  xml += "  </Collection>\n</VTKFile>\n";
  AtomicWriter f(path_);
  f.write(xml);
  f.commit();
}

void Series::restore_up_to(double t) {
  entries_.clear();
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return;  // the earlier run wrote no record yet
  std::ifstream in(path_, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in)
    throw RunError(fmt::format("VTK output {}: cannot read: {}", path_, std::strerror(errno)));
  const std::string text = ss.str();

  // Only this class writes the file, so a scan of the <DataSet .../> tags suffices.
  auto bad = [&](const std::string& why) {
    return RunError(fmt::format("VTK output {}: cannot resume from it: {}", path_, why));
  };
  for (std::size_t at = text.find("<DataSet"); at != std::string::npos;
       at = text.find("<DataSet", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) throw bad("unterminated <DataSet");
    const std::string_view tag(text.data() + at, end - at);
    auto attribute = [&](std::string_view name) -> std::string {
      const std::string key =
          fmt::format(" {}=\"", name);  // not " " + s: a false GCC 12 -Wrestrict
      const std::size_t k = tag.find(key);
      if (k == std::string_view::npos) throw bad(fmt::format("a DataSet lacks {}", name));
      const std::size_t v = k + key.size();
      const std::size_t q = tag.find('"', v);
      if (q == std::string_view::npos) throw bad(fmt::format("unterminated {}", name));
      return unescape(tag.substr(v, q - v));
    };
    const std::string ts = attribute("timestep");
    double time = 0;
    const auto [ptr, err] = std::from_chars(ts.data(), ts.data() + ts.size(), time);
    if (err != std::errc{} || ptr != ts.data() + ts.size())
      throw bad(fmt::format("timestep \"{}\" is not a number", ts));
    std::string file = attribute("file");
    if (time <= t) entries_.emplace_back(time, std::move(file));
  }
}

void Series::drop_files_containing(std::string_view part) {
  std::erase_if(entries_, [&](const auto& e) { return e.second.find(part) != std::string::npos; });
}

}  // namespace mpmx::io::vtk
