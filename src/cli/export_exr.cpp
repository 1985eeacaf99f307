// OpenEXR export of 1-D/2-D tables (see export_exr.hpp). The values are the table's
// values rounded to float32: exact for float32 ("compact") tables.
#include "cli/export_exr.hpp"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace brdftab::cli {

void write_exr(const lookup::LoadedTable& lt, const std::string& source_file, const std::filesystem::path& path) {
  const lookup::Table& t = lt.table;
  const int rank = t.rank();
  if (rank < 1 || rank > 2)
    throw std::runtime_error("table '" + t.name() + "' has rank " + std::to_string(rank) +
                             "; OpenEXR export covers 1-D and 2-D tables");
  const int width = t.axis(rank - 1).n, height = rank == 2 ? t.axis(0).n : 1;
  std::vector<float> pixels(static_cast<std::size_t>(width) * height);
  std::vector<int> idx(rank);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (rank == 2) idx = {y, x};
      else idx = {x};
      pixels[static_cast<std::size_t>(y) * width + x] = static_cast<float>(t.at_index(idx));
    }

  Imf::Header h(width, height);
  h.compression() = Imf::ZIP_COMPRESSION;
  h.channels().insert("Y", Imf::Channel(Imf::FLOAT));
  auto str = [&](const std::string& key, const std::string& v) { h.insert(key, Imf::StringAttribute(v)); };
  auto num = [&](const std::string& key, double v) { h.insert(key, Imf::DoubleAttribute(v)); };
  str("brdftab.dataset", t.name());
  str("brdftab.source_file", source_file);
  str("brdftab.quantity", lt.info.attribute_string("quantity"));
  str("brdftab.storage", t.storage() == lookup::Storage::float32 ? "float32" : "float64 rounded to float32");
  str("brdftab.interpolation", std::string(lookup::interpolation_name(t.interpolation())));
  h.insert("brdftab.rank", Imf::IntAttribute(rank));
  for (int d = 0; d < rank; ++d) {
    const lookup::Axis& a = t.axis(d);
    const std::string p = "brdftab.axis" + std::to_string(d) + ".";
    str(p + "name", a.name);
    str(p + "units", a.units);
    str(p + "transform", std::string(lookup::transform_name(a.transform)));
    str(p + "image_axis", d == rank - 1 ? "x" : "y");
    h.insert(p + "n", Imf::IntAttribute(a.n));
    num(p + "scale", a.scale);
    num(p + "u_first", a.u0);
    num(p + "u_step", a.du);
    num(p + "x_lo", a.x_lo);
    num(p + "x_hi", a.x_hi);
  }
  for (const auto& [key, value] : lt.info.attributes) {
    const std::string name = "brdftab.attr." + key;
    if (const auto* s = std::get_if<std::string>(&value)) str(name, *s);
    else if (const auto* v = std::get_if<double>(&value)) num(name, *v);
    else if (const auto* i = std::get_if<long long>(&value)) num(name, static_cast<double>(*i));
  }

  try {
    Imf::OutputFile file(path.string().c_str(), h);
    Imf::FrameBuffer fb;
    fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), sizeof(float),
                              sizeof(float) * static_cast<std::size_t>(width)));
    file.setFrameBuffer(fb);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + e.what());
  }
}

}  // namespace brdftab::cli
