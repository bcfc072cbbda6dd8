// ctest-label: unit
// VTK XML output: files are read back by VTK itself (tests/io/vtk_readback.py, Debian's
// python3-vtk9) and every value must come back bit for bit; plus atomic writes, error
// messages and resuming a .pvd series.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/io/vtk.hpp"

namespace fs = std::filesystem;
namespace vtk = mpmx::io::vtk;

namespace {

// --- A JSON reader just big enough for the script's output (no library in the deps). ---

struct Json {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<Json> items;        // Array elements, or Object values
  std::vector<std::string> keys;  // Object keys, parallel to items

  const Json& operator[](const std::string& key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == key) return items[i];
    throw std::runtime_error("JSON: no key " + key);
  }
  const Json& operator[](std::size_t i) const { return items.at(i); }
  std::size_t size() const { return items.size(); }
  std::vector<double> numbers() const {
    std::vector<double> v;
    for (const Json& j : items) v.push_back(j.number);
    return v;
  }
};

class JsonParser {
 public:
  explicit JsonParser(std::string_view s) : s_(s) {}
  Json parse() {
    Json j = value();
    space();
    if (i_ != s_.size()) fail("trailing text");
    return j;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error("JSON at " + std::to_string(i_) + ": " + why);
  }
  void space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    space();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("expected ") + c);
  }
  bool word(std::string_view w) {
    if (s_.substr(i_, w.size()) != w) return false;
    i_ += w.size();
    return true;
  }
  std::string str() {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) fail("bad escape");
      char e = s_[i_++];
      switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          // ASCII is all the test's names use; anything else is kept as a marker.
          unsigned code = std::stoul(std::string(s_.substr(i_, 4)), nullptr, 16);
          i_ += 4;
          out += code < 0x80 ? static_cast<char>(code) : '?';
          break;
        }
        default: out += e;  // \" \\ \/
      }
    }
    expect('"');
    return out;
  }
  Json value() {
    space();
    Json j;
    if (i_ >= s_.size()) fail("unexpected end");
    char c = s_[i_];
    if (c == '{') {
      ++i_;
      j.kind = Json::Object;
      if (eat('}')) return j;
      do {
        space();
        j.keys.push_back(str());
        expect(':');
        j.items.push_back(value());
      } while (eat(','));
      expect('}');
    } else if (c == '[') {
      ++i_;
      j.kind = Json::Array;
      if (eat(']')) return j;
      do j.items.push_back(value());
      while (eat(','));
      expect(']');
    } else if (c == '"') {
      j.kind = Json::String;
      j.string = str();
    } else if (word("null")) {
      j.kind = Json::Null;
    } else if (word("true")) {
      j.kind = Json::Bool;
      j.boolean = true;
    } else if (word("false")) {
      j.kind = Json::Bool;
    } else {
      // from_chars reads the shortest repr Python prints back to the same double.
      j.kind = Json::Number;
      auto [p, err] = std::from_chars(s_.data() + i_, s_.data() + s_.size(), j.number);
      if (err != std::errc{}) fail("bad number");
      i_ = p - s_.data();
    }
    return j;
  }
  std::string_view s_;
  std::size_t i_ = 0;
};

// --- Helpers ---

// A fresh directory per test (ctest runs each test in its own process, maybe in
// parallel), removed however the test ends, skips included.
struct TempDir {
  fs::path path;
  TempDir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path = fs::temp_directory_path() /
           ("mpmx_vtk_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Runs the readback script on `files`; nullopt when VTK is not installed.
std::optional<Json> read_back(const std::vector<fs::path>& files) {
  std::string cmd =
      std::string(MPMX_PYTHON) + " '" + MPMX_SOURCE_DIR + "/tests/io/vtk_readback.py'";
  for (const auto& f : files) cmd += " '" + f.string() + "'";
  std::FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) throw std::runtime_error("cannot run " + cmd);
  std::string out;
  char buf[65536];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int status = ::pclose(p);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("vtk_readback.py failed (see stderr): " + cmd);
  return JsonParser(out).parse();
}

#define READ_BACK_OR_SKIP(var, ...)                                                      \
  auto var##_opt = read_back(__VA_ARGS__);                                               \
  if (!var##_opt)                                                                        \
    GTEST_SKIP() << "python3-vtk9 is not installed (scripts/install-deps installs it); " \
                    "the VTK readback is not checked";                                   \
  const Json& var = *var##_opt

// Bit-exact: -0.0 differs from 0.0, and equal NaN payloads would match.
void expect_bits_equal(const std::vector<double>& want, const std::vector<double>& got,
                       const std::string& what) {
  ASSERT_EQ(want.size(), got.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint64_t>(want[i]), std::bit_cast<std::uint64_t>(got[i]))
        << what << "[" << i << "]: wrote " << want[i] << ", VTK read " << got[i];
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Values no decimal printer would round-trip by accident: thirds, tiny, huge, subnormal,
// negative zero, and neighbours one ulp apart.
double distinctive(std::size_t i, int salt) {
  const double base = (static_cast<double>(i) + salt / 7.0) / 3.0;
  switch (i % 6) {
    case 0: return base * std::numbers::pi;
    case 1: return -base * 1e-300;
    case 2: return std::nextafter(base * 1e200, 0.0);
    case 3: return i == 3 ? -0.0 : std::numeric_limits<double>::denorm_min() * (i + salt);
    case 4: return std::nextafter(1.0, 2.0) + salt;
    default: return -base;
  }
}

vtk::Field make_field(std::string name, int components, std::size_t n, int salt) {
  vtk::Field f{std::move(name), components, {}};
  for (std::size_t k = 0; k < n * components; ++k) f.values.push_back(distinctive(k, salt));
  return f;
}

// A 10 x 10 lattice, slightly jittered, z = 0 (a 2-D caller).
std::vector<double> lattice_points(std::size_t n) {
  std::vector<double> xyz;
  for (std::size_t i = 0; i < n; ++i) {
    xyz.push_back(0.1 * static_cast<double>(i % 10) + 1e-3 / (i + 1.0));
    xyz.push_back(0.1 * static_cast<double>(i / 10) - 1.0 / 3.0);
    xyz.push_back(0.0);
  }
  return xyz;
}

void expect_array(const Json& a, const vtk::Field& f) {
  EXPECT_EQ(a["name"].string, f.name);
  EXPECT_EQ(a["components"].number, f.components) << f.name;
  EXPECT_EQ(a["type"].string, "double") << f.name;
  expect_bits_equal(f.values, a["values"].numbers(), f.name);
}

bool any_tmp_in(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".tmp") return true;
  return false;
}

// The message of the error E that f throws: a write the system refuses is the machine's
// failure (SystemError: exit 1, the file and the system's reason), a file mpmx cannot
// use (damaged) a RunError naming it.
template <class E>
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "(not the error expected)";
}

}  // namespace

TEST(Vtk, PointsReadBackByVtkBitExact) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const std::size_t n = 100;
  const auto xyz = lattice_points(n);
  const std::vector<vtk::Field> fields = {
      make_field("density", 1, n, 1), make_field("velocity", 3, n, 2),
      make_field("stress", 9, n, 3), make_field(R"(odd <&> "name')", 1, n, 4)};
  const fs::path file = dir / "points.vtu";
  vtk::write_points(file, xyz, fields);

  READ_BACK_OR_SKIP(out, {file});
  const Json& g = out[0];
  EXPECT_EQ(g["kind"].string, "vtu");
  EXPECT_EQ(g["number_of_points"].number, n);
  EXPECT_EQ(g["number_of_cells"].number, n);
  ASSERT_EQ(g["cell_types"].size(), 1u);
  EXPECT_EQ(g["cell_types"][0].number, 1) << "VTK_VERTEX";
  EXPECT_EQ(g["points_type"].string, "double");
  expect_bits_equal(xyz, g["points"].numbers(), "points");

  ASSERT_EQ(g["arrays"].size(), fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) expect_array(g["arrays"][i], fields[i]);
  EXPECT_EQ(g["arrays"][2]["components"].number, 9) << "the tensor has 9 components";
  EXPECT_EQ(g["attributes"]["scalars"].string, "density");
  EXPECT_EQ(g["attributes"]["vectors"].string, "velocity");
  EXPECT_EQ(g["attributes"]["tensors"].string, "stress");
}

TEST(Vtk, EmptyPointSetIsValid) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const fs::path file = dir / "empty.vtu";
  vtk::write_points(file, {}, {vtk::Field{"mass", 1, {}}});
  READ_BACK_OR_SKIP(out, {file});
  EXPECT_EQ(out[0]["number_of_points"].number, 0);
}

TEST(Vtk, ImageReadBackByVtkBitExact) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const std::array<int, 3> nodes = {5, 4, 1};
  const std::array<double, 3> origin = {-1.25, 1.0 / 3.0, 0.0};
  const std::array<double, 3> spacing = {0.1, std::nextafter(0.2, 1.0), 1.0};
  const std::size_t n = 5 * 4;
  const std::vector<vtk::Field> fields = {make_field("mass", 1, n, 5),
                                          make_field("momentum", 3, n, 6)};
  const fs::path file = dir / "grid.vti";
  vtk::write_image(file, nodes, origin, spacing, fields);

  READ_BACK_OR_SKIP(out, {file});
  const Json& g = out[0];
  EXPECT_EQ(g["kind"].string, "vti");
  EXPECT_EQ(g["number_of_points"].number, n);
  ASSERT_EQ(g["dimensions"].size(), 3u);
  for (int d = 0; d < 3; ++d) EXPECT_EQ(g["dimensions"][d].number, nodes[d]);
  expect_bits_equal({origin.begin(), origin.end()}, g["origin"].numbers(), "origin");
  expect_bits_equal({spacing.begin(), spacing.end()}, g["spacing"].numbers(), "spacing");
  ASSERT_EQ(g["arrays"].size(), fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) expect_array(g["arrays"][i], fields[i]);
  EXPECT_EQ(g["attributes"]["scalars"].string, "mass");
  EXPECT_EQ(g["attributes"]["vectors"].string, "momentum");
  EXPECT_EQ(g["attributes"]["tensors"].kind, Json::Null);
}

TEST(Vtk, SeriesReadBackByVtk) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  fs::create_directories(dir / "vtk");
  vtk::Series series((dir / "particles.pvd").string());
  const std::vector<double> times = {0.0, 0.1, 1.0 / 3.0};
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::size_t n = 10 * (k + 1);
    const std::string rel = "vtk/particles_" + std::to_string(k) + ".vtu";
    vtk::write_points(dir / rel, lattice_points(n), {make_field("stress", 9, n, 7)});
    series.add(times[k], rel);
  }
  EXPECT_FALSE(any_tmp_in(dir));

  READ_BACK_OR_SKIP(out, {dir / "particles.pvd"});
  const Json& entries = out[0]["entries"];
  ASSERT_EQ(entries.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    expect_bits_equal({times[k]}, {entries[k]["time"].number}, "time");
    EXPECT_EQ(entries[k]["file"].string, "vtk/particles_" + std::to_string(k) + ".vtu");
    EXPECT_EQ(entries[k]["kind"].string, "vtu");
    EXPECT_EQ(entries[k]["number_of_points"].number, 10 * (k + 1));
  }
}

// Without VTK: the header declares what ParaView needs, whatever reads the file.
TEST(Vtk, HeaderDeclaresBinaryTensorLittleEndian) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const fs::path file = dir / "p.vtu";
  vtk::write_points(file, lattice_points(4), {make_field("stress", 9, 4, 1)});
  const std::string text = read_bytes(file);
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  EXPECT_NE(text.find(R"(byte_order="LittleEndian")"), std::string::npos);
  EXPECT_NE(text.find(R"(header_type="UInt64")"), std::string::npos);
  EXPECT_NE(text.find(R"(<PointData Tensors="stress">)"), std::string::npos);
  EXPECT_NE(text.find(R"(type="Float64" Name="stress" NumberOfComponents="9")"), std::string::npos);
  EXPECT_NE(text.find(R"(<AppendedData encoding="raw">)"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 11), "</VTKFile>\n");
}

TEST(Vtk, WritesAtomicallyAndOverwrites) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const fs::path file = dir / "p.vtu";
  vtk::write_points(file, lattice_points(4), {make_field("a", 1, 4, 1)});
  const auto first = fs::file_size(file);
  vtk::write_points(file, lattice_points(40), {make_field("a", 1, 40, 1)});
  EXPECT_GT(fs::file_size(file), first) << "the second write replaced the first";
  vtk::write_image(dir / "g.vti", {2, 2, 2}, {0, 0, 0}, {1, 1, 1}, {make_field("m", 1, 8, 1)});
  vtk::Series s((dir / "s.pvd").string());
  s.add(0.0, "p.vtu");
  EXPECT_FALSE(any_tmp_in(dir));

  // A rename that fails (the target is a directory) throws and leaves no temporary.
  fs::create_directories(dir / "blocked.vtu");
  const std::string msg =
      error_of<mpmx::SystemError>([&] { vtk::write_points(dir / "blocked.vtu", lattice_points(1), {}); });
  EXPECT_NE(msg.find((dir / "blocked.vtu").string()), std::string::npos) << msg;
  EXPECT_FALSE(any_tmp_in(dir));
  EXPECT_TRUE(fs::is_directory(dir / "blocked.vtu"));
}

TEST(Vtk, MissingDirectoryThrowsSystemErrorNamingPath) {
  const TempDir tmp;
  const fs::path& root = tmp.path;
  const fs::path dir = root / "no" / "such" / "dir";
  const std::string p = (dir / "p.vtu").string(), g = (dir / "g.vti").string(),
                    s = (dir / "s.pvd").string();
  std::string msg = error_of<mpmx::SystemError>([&] { vtk::write_points(p, lattice_points(2), {}); });
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
  msg = error_of<mpmx::SystemError>([&] { vtk::write_image(g, {1, 1, 1}, {0, 0, 0}, {1, 1, 1}, {}); });
  EXPECT_NE(msg.find(g), std::string::npos) << msg;
  vtk::Series series(s);
  msg = error_of<mpmx::SystemError>([&] { series.add(1.0, "x.vtu"); });
  EXPECT_NE(msg.find(s), std::string::npos) << msg;
  EXPECT_TRUE(series.entries().empty()) << "a failed add is not listed";
  EXPECT_FALSE(fs::exists(root / "no"));
}

TEST(Vtk, MismatchedSizesAreRejected) {
  const std::string p = (fs::temp_directory_path() / "mpmx_vtk_never.vtu").string();
  EXPECT_THROW(vtk::write_points(p, {1.0, 2.0}, {}), std::invalid_argument);
  EXPECT_THROW(vtk::write_points(p, lattice_points(3), {make_field("a", 3, 2, 1)}),
               std::invalid_argument);
  EXPECT_THROW(
      vtk::write_points(p, lattice_points(2), {make_field("a", 1, 2, 1), make_field("a", 1, 2, 2)}),
      std::invalid_argument);
  EXPECT_THROW(vtk::write_image(p, {0, 1, 1}, {0, 0, 0}, {1, 1, 1}, {}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(p));
}

TEST(Vtk, SeriesRestoreUpToKeepsEarlierEntries) {
  const TempDir tmp;
  const fs::path& dir = tmp.path;
  const std::string pvd = (dir / "particles.pvd").string();
  const std::vector<double> times = {0.0, 0.1, 0.2, 1.0 / 3.0, 0.5};
  {
    vtk::Series first(pvd);
    for (std::size_t k = 0; k < times.size(); ++k)
      first.add(times[k], "vtk/p_" + std::to_string(k) + ".vtu");
  }

  // Resuming from a checkpoint at t = 1/3 keeps that record (time <= t) and drops later.
  vtk::Series resumed(pvd);
  resumed.restore_up_to(1.0 / 3.0);
  ASSERT_EQ(resumed.entries().size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    expect_bits_equal({times[k]}, {resumed.entries()[k].first}, "time");
    EXPECT_EQ(resumed.entries()[k].second, "vtk/p_" + std::to_string(k) + ".vtu");
  }
  resumed.add(0.4, "vtk/p_new.vtu");

  vtk::Series reread(pvd);
  reread.restore_up_to(std::numeric_limits<double>::infinity());
  ASSERT_EQ(reread.entries().size(), 5u);
  EXPECT_EQ(reread.entries()[4].first, 0.4);
  EXPECT_EQ(reread.entries()[4].second, "vtk/p_new.vtu");

  // Before anything: no entries. No .pvd yet: none either, and no error.
  reread.restore_up_to(-1.0);
  EXPECT_TRUE(reread.entries().empty());
  vtk::Series fresh((dir / "none.pvd").string());
  fresh.restore_up_to(10.0);
  EXPECT_TRUE(fresh.entries().empty());

  // A damaged file is an error naming it, not a silently empty series.
  std::ofstream(dir / "bad.pvd") << "<VTKFile><Collection><DataSet timestep=\"x\" file=\"a\"/>";
  vtk::Series bad((dir / "bad.pvd").string());
  const std::string msg = error_of<mpmx::RunError>([&] { bad.restore_up_to(1.0); });
  EXPECT_NE(msg.find((dir / "bad.pvd").string()), std::string::npos) << msg;
}
