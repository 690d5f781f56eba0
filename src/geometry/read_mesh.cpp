#include "geometry/read_mesh.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

namespace rollcheck::geometry
{
namespace
{
struct Builder
{
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> faces;
  int index_base = 0; ///< the file's first vertex index: 1 in OBJ, 0 in OFF and PLY

  /// Fans a polygon (0-based indices) into triangles.
  void add_polygon(const std::vector<int>& poly, const std::string& where)
  {
    if (poly.size() < 3)
      throw InputError(fmt::format("{}: a face has fewer than 3 vertices", where));
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      faces.push_back({poly[0], poly[k], poly[k + 1]});
  }

  SurfaceMesh finish(const std::string& name) const
  {
    if (vertices.empty() || faces.empty())
      throw InputError(fmt::format("mesh file '{}': no vertices or no faces", name));
    SurfaceMesh mesh;
    mesh.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      for (int j = 0; j < 3; ++j)
        mesh.vertices(static_cast<Eigen::Index>(i), j) = vertices[i][j];
    mesh.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (int j = 0; j < 3; ++j)
      {
        const int v = faces[i][j];
        if (v < 0 || v >= static_cast<int>(vertices.size()))
          throw InputError(fmt::format("mesh file '{}': face {} refers to vertex index {}, but the {} vertices "
                                       "are numbered {} to {}",
                                       name, i + 1, static_cast<long long>(v) + index_base, vertices.size(),
                                       index_base, static_cast<long long>(vertices.size()) - 1 + index_base));
        mesh.faces(static_cast<Eigen::Index>(i), j) = v;
      }
    if (!mesh.vertices.allFinite())
      throw InputError(fmt::format("mesh file '{}': a vertex coordinate is NaN or infinite", name));
    if (const double largest = mesh.vertices.cwiseAbs().maxCoeff(); largest > max_mesh_coordinate_m)
      throw InputError(fmt::format("mesh file '{}': a vertex coordinate of {:g} m is beyond the {:g} m a mesh may "
                                   "reach (its volume and inertia would overflow)",
                                   name, largest, max_mesh_coordinate_m));
    return mesh;
  }
};

double parse_double(const std::string& token, const std::string& where)
{
  try
  {
    std::size_t used = 0;
    const double value = std::stod(token, &used);
    if (used != token.size())
      throw std::invalid_argument(token);
    return value;
  }
  catch (const std::exception&)
  {
    throw InputError(fmt::format("{}: '{}' is not a number", where, token));
  }
}

bool fits_int(double value)
{
  return value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
}

int parse_int(const std::string& token, const std::string& where)
{
  const double value = parse_double(token, where);
  if (!fits_int(value) || value != std::trunc(value))
    throw InputError(fmt::format("{}: '{}' is not an integer in the range of int", where, token));
  return static_cast<int>(value);
}

/// PLY lists hold integers as any numeric type; truncated like a C cast, but
/// a value out of int's range is bad input, not undefined behaviour.
int checked_int(double value, const std::string& where)
{
  if (!fits_int(value))
    throw InputError(fmt::format("{}: {} is not an index or count in the range of int", where, value));
  return static_cast<int>(value);
}

/// A count read from a file sizes an allocation only once the rest of the
/// file can hold that many items: a few bytes must not claim gigabytes.
void check_declared_count(long long count, std::size_t available, const std::string& where, std::string_view items,
                          std::string_view units)
{
  if (count > 0 && static_cast<unsigned long long>(count) > available)
    throw InputError(fmt::format("{} declares {} {} but the rest of the file holds only {} {}", where, count, items,
                                 available, units));
}

SurfaceMesh read_obj(std::istream& in, const std::string& name)
{
  Builder b;
  b.index_base = 1;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno)
  {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    const std::string where = fmt::format("{}:{}", name, lineno);
    if (kind == "v")
    {
      std::array<double, 3> p{};
      for (double& x : p)
      {
        std::string token;
        if (!(words >> token))
          throw InputError(fmt::format("{}: a vertex needs 3 coordinates", where));
        x = parse_double(token, where);
      }
      b.vertices.push_back(p);
    }
    else if (kind == "f")
    {
      std::vector<int> poly;
      for (std::string token; words >> token;)
      {
        // "v", "v/vt", "v//vn", "v/vt/vn"; negative indices count from the end.
        const int v = parse_int(token.substr(0, token.find('/')), where);
        if (v == 0)
          throw InputError(fmt::format("{}: vertex index 0 (OBJ numbers vertices from 1)", where));
        if (v < 0 && -static_cast<long long>(v) > static_cast<long long>(b.vertices.size()))
          throw InputError(fmt::format("{}: relative vertex index {} reaches before the first of the {} vertices "
                                       "read so far",
                                       where, v, b.vertices.size()));
        poly.push_back(v > 0 ? v - 1 : static_cast<int>(b.vertices.size()) + v);
      }
      b.add_polygon(poly, where);
    }
  }
  return b.finish(name);
}

SurfaceMesh read_off(std::istream& in, const std::string& name)
{
  // Tokens with comments removed; the header may be "OFF" alone or "OFF nv nf ne".
  std::vector<std::string> tokens;
  for (std::string line; std::getline(in, line);)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    for (std::string t; words >> t;)
      tokens.push_back(t);
  }
  std::size_t at = 0;
  auto next = [&]() -> const std::string& {
    if (at >= tokens.size())
      throw InputError(fmt::format("mesh file '{}': OFF data ends early", name));
    return tokens[at++];
  };
  if (next() != "OFF")
    throw InputError(fmt::format("mesh file '{}': does not start with OFF", name));
  const int nv = parse_int(next(), name), nf = parse_int(next(), name);
  next();
  if (nv < 0 || nf < 0)
    throw InputError(fmt::format("mesh file '{}': negative vertex or face count", name));
  Builder b;
  for (int i = 0; i < nv; ++i)
    b.vertices.push_back({parse_double(next(), name), parse_double(next(), name), parse_double(next(), name)});
  for (int i = 0; i < nf; ++i)
  {
    const std::string where = fmt::format("{}: face {}", name, i + 1);
    const int n = parse_int(next(), name);
    check_declared_count(n, tokens.size() - at, where, "vertices", "values");
    std::vector<int> poly(static_cast<std::size_t>(std::max(n, 0)));
    for (int& v : poly)
      v = parse_int(next(), name);
    b.add_polygon(poly, where);
  }
  return b.finish(name);
}

/// STL stores triangles with repeated corners; corners with identical
/// coordinates become one vertex, numbered in order of first appearance.
struct VertexWelder
{
  Builder& b;
  std::map<std::array<double, 3>, int> index;
  int operator()(const std::array<double, 3>& p)
  {
    auto [it, inserted] = index.emplace(p, static_cast<int>(b.vertices.size()));
    if (inserted)
      b.vertices.push_back(p);
    return it->second;
  }
};

SurfaceMesh read_stl(const std::string& bytes, const std::string& name)
{
  Builder b;
  VertexWelder weld{b, {}};
  const bool sized_binary = bytes.size() >= 84 && [&] {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    return bytes.size() == 84 + 50 * static_cast<std::size_t>(n);
  }();
  if (sized_binary)
  {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    for (std::uint32_t t = 0; t < n; ++t)
    {
      const char* rec = bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12;
      std::vector<int> tri;
      for (int k = 0; k < 3; ++k)
      {
        float xyz[3];
        std::memcpy(xyz, rec + 12 * k, 12);
        tri.push_back(weld({xyz[0], xyz[1], xyz[2]}));
      }
      b.add_polygon(tri, name);
    }
    return b.finish(name);
  }
  if (bytes.rfind("solid", 0) != 0)
    throw InputError(fmt::format("mesh file '{}': neither ASCII STL nor a binary STL of consistent size", name));
  std::istringstream in(bytes);
  std::vector<int> tri;
  for (std::string word; in >> word;)
  {
    if (word == "vertex")
    {
      std::array<double, 3> p{};
      for (double& x : p)
      {
        std::string token;
        in >> token;
        x = parse_double(token, name);
      }
      tri.push_back(weld(p));
    }
    else if (word == "endloop")
    {
      b.add_polygon(tri, name);
      tri.clear();
    }
  }
  return b.finish(name);
}

struct PlyProperty
{
  std::string name;
  std::string type;       ///< "float", ...; a list: "list:" and its entries' type
  std::string count_type; ///< a list's count type
};

struct PlyElement
{
  std::string name;
  long count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader
{
  std::string format;
  std::vector<PlyElement> elements;
  std::size_t data_start = 0; ///< the byte after the line 'end_header'
};

PlyHeader read_ply_header(const std::string& bytes, const std::string& name)
{
  const auto header_end = bytes.find("end_header");
  if (bytes.rfind("ply", 0) != 0 || header_end == std::string::npos)
    throw InputError(fmt::format("mesh file '{}': not a PLY file", name));
  PlyHeader h;
  std::istringstream header(bytes.substr(0, header_end));
  for (std::string line; std::getline(header, line);)
  {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "format")
      words >> h.format;
    else if (kind == "element")
    {
      PlyElement e;
      if (!(words >> e.name >> e.count) || e.count < 0)
        throw InputError(fmt::format("mesh file '{}': PLY header line '{}' does not declare a count >= 0", name,
                                     line));
      h.elements.push_back(e);
    }
    else if (kind == "property" && !h.elements.empty())
    {
      std::string type;
      words >> type;
      PlyProperty p;
      if (type == "list")
      {
        words >> p.count_type >> p.type >> p.name;
        p.type = "list:" + p.type;
      }
      else
      {
        p.type = type;
        words >> p.name;
      }
      h.elements.back().properties.push_back(p);
    }
  }
  if (h.format != "ascii" && h.format != "binary_little_endian")
    throw InputError(fmt::format("mesh file '{}': PLY format '{}' is not supported", name, h.format));
  const auto header_line_end = bytes.find('\n', header_end);
  if (header_line_end == std::string::npos)
    throw InputError(fmt::format("mesh file '{}': PLY header line 'end_header' does not end", name));
  h.data_start = header_line_end + 1;
  return h;
}

/// The values of a PLY body, one at a time, as text tokens (ascii) or as
/// little-endian binary values of the declared types.
class PlyValues
{
public:
  PlyValues(const std::string& bytes, const PlyHeader& header, const std::string& name)
      : bytes_(bytes), name_(name), ascii_(header.format == "ascii"), pos_(header.data_start),
        text_(ascii_ ? bytes.substr(pos_) : std::string())
  {
  }

  /// Bytes not yet read (for ascii: all after the header).
  std::size_t remaining() const { return bytes_.size() - pos_; }

  double next(const std::string& type)
  {
    if (ascii_)
    {
      std::string token;
      if (!(text_ >> token))
        throw InputError(fmt::format("mesh file '{}': PLY data ends early", name_));
      return parse_double(token, name_);
    }
    const std::size_t n = size_of(type);
    if (pos_ + n > bytes_.size())
      throw InputError(fmt::format("mesh file '{}': PLY data ends early", name_));
    const char* p = bytes_.data() + pos_;
    pos_ += n;
    auto get = [p](auto value) {
      std::memcpy(&value, p, sizeof value);
      return static_cast<double>(value);
    };
    if (type == "char" || type == "int8") return get(std::int8_t{});
    if (type == "uchar" || type == "uint8") return get(std::uint8_t{});
    if (type == "short" || type == "int16") return get(std::int16_t{});
    if (type == "ushort" || type == "uint16") return get(std::uint16_t{});
    if (type == "int" || type == "int32") return get(std::int32_t{});
    if (type == "uint" || type == "uint32") return get(std::uint32_t{});
    if (type == "float" || type == "float32") return get(float{});
    return get(double{});
  }

private:
  std::size_t size_of(const std::string& t) const
  {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
      return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
      return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
      return 4;
    if (t == "double" || t == "float64")
      return 8;
    throw InputError(fmt::format("mesh file '{}': unknown PLY type '{}'", name_, t));
  }

  const std::string& bytes_;
  const std::string& name_;
  bool ascii_;
  std::size_t pos_;
  std::istringstream text_;
};

/// Reads the items of one element: the x, y, z of a vertex, the vertex
/// indices of a face; other properties are read and passed over.
void read_ply_element(const PlyElement& e, PlyValues& values, Builder& b, const std::string& name)
{
  // Every item takes at least one byte (a list's count, a value).
  check_declared_count(e.count, values.remaining(), fmt::format("{}: element '{}'", name, e.name), "items", "bytes");
  for (long i = 0; i < e.count; ++i)
  {
    std::array<double, 3> p{};
    for (const PlyProperty& prop : e.properties)
    {
      if (prop.type.rfind("list:", 0) == 0)
      {
        const std::string where = fmt::format("{}: {} {}", name, e.name, i + 1);
        const int n = checked_int(values.next(prop.count_type), where);
        check_declared_count(n, values.remaining(), where, "list entries", "bytes");
        std::vector<int> poly(static_cast<std::size_t>(std::max(n, 0)));
        for (int& v : poly)
          v = checked_int(values.next(prop.type.substr(5)), where);
        if (e.name == "face" && (prop.name == "vertex_indices" || prop.name == "vertex_index"))
          b.add_polygon(poly, where);
        continue;
      }
      const double value = values.next(prop.type);
      if (e.name == "vertex" && prop.name.size() == 1 && prop.name[0] >= 'x' && prop.name[0] <= 'z')
        p[prop.name[0] - 'x'] = value;
    }
    if (e.name == "vertex")
      b.vertices.push_back(p);
  }
}

SurfaceMesh read_ply(const std::string& bytes, const std::string& name)
{
  const PlyHeader header = read_ply_header(bytes, name);
  PlyValues values(bytes, header, name);
  Builder b;
  for (const PlyElement& e : header.elements)
    read_ply_element(e, values, b, name);
  return b.finish(name);
}
} // namespace

SurfaceMesh read_mesh(const std::filesystem::path& path)
{
  const std::string name = path.string();
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".ply")
    throw InputError(fmt::format("mesh file '{}': unknown extension '{}' (use .obj, .stl, .ply or .off)", name, ext));
  const std::string bytes = core::read_bounded_file(path, "mesh file", max_mesh_file_bytes);
  if (ext == ".obj" || ext == ".off")
  {
    std::istringstream in(bytes);
    return ext == ".obj" ? read_obj(in, name) : read_off(in, name);
  }
  if (ext == ".stl")
    return read_stl(bytes, name);
  return read_ply(bytes, name);
}
} // namespace rollcheck::geometry
