// `brdftab export --format exr`: the image is read back with OpenEXR's C core library
// (openexr.h: its own header parser and decoder, no code shared with the C++ Imf writer
// that export uses in OpenEXR 3.1) and compared with the table as brdftab's HDF5 reader
// sees it: every pixel equals the float32 value bit for bit, and the header attributes hold
// the axis metadata.
#include <doctest/doctest.h>
#include <openexr.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {

struct ExrImage {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;  // channel 0, row-major
  exr_context_t ctx = nullptr;
  ~ExrImage() {
    if (ctx) exr_finish(&ctx);
  }
  std::string str(const std::string& name) const {
    int32_t len = 0;
    const char* s = nullptr;
    if (exr_attr_get_string(ctx, 0, name.c_str(), &len, &s) != EXR_ERR_SUCCESS) return "<missing " + name + ">";
    return std::string(s, static_cast<std::size_t>(len));
  }
  double num(const std::string& name) const {
    double v = NAN;
    if (exr_attr_get_double(ctx, 0, name.c_str(), &v) != EXR_ERR_SUCCESS) return NAN;
    return v;
  }
  int integer(const std::string& name) const {
    int32_t v = -1;
    if (exr_attr_get_int(ctx, 0, name.c_str(), &v) != EXR_ERR_SUCCESS) return -1;
    return v;
  }
};

void check(exr_result_t r, const char* what) {
  if (r != EXR_ERR_SUCCESS) throw std::runtime_error(std::string(what) + ": " + exr_get_default_error_message(r));
}

// Reads every scanline chunk of part 0, channel 0 as float32.
void read_exr(const fs::path& path, ExrImage& img) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  check(exr_start_read(&img.ctx, path.c_str(), &init), "exr_start_read");
  exr_attr_box2i_t dw;
  check(exr_get_data_window(img.ctx, 0, &dw), "exr_get_data_window");
  img.width = dw.max.x - dw.min.x + 1;
  img.height = dw.max.y - dw.min.y + 1;
  const exr_attr_chlist_t* ch = nullptr;
  check(exr_get_channels(img.ctx, 0, &ch), "exr_get_channels");
  for (int c = 0; c < ch->num_channels; ++c) img.channels.emplace_back(ch->entries[c].name.str);
  img.pixels.assign(static_cast<std::size_t>(img.width) * img.height, NAN);
  int32_t lines = 0;
  check(exr_get_scanlines_per_chunk(img.ctx, 0, &lines), "exr_get_scanlines_per_chunk");
  for (int y = dw.min.y; y <= dw.max.y; y += lines) {
    exr_chunk_info_t info;
    check(exr_read_scanline_chunk_info(img.ctx, 0, y, &info), "exr_read_scanline_chunk_info");
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    check(exr_decoding_initialize(img.ctx, 0, &info, &dec), "exr_decoding_initialize");
    REQUIRE(dec.channel_count == 1);
    dec.channels[0].decode_to_ptr =
        reinterpret_cast<uint8_t*>(img.pixels.data() + static_cast<std::size_t>(info.start_y - dw.min.y) * img.width);
    dec.channels[0].user_bytes_per_element = 4;
    dec.channels[0].user_data_type = EXR_PIXEL_FLOAT;
    dec.channels[0].user_pixel_stride = 4;
    dec.channels[0].user_line_stride = 4 * img.width;
    check(exr_decoding_choose_default_routines(img.ctx, 0, &dec), "exr_decoding_choose_default_routines");
    check(exr_decoding_run(img.ctx, 0, &dec), "exr_decoding_run");
    exr_decoding_destroy(img.ctx, &dec);
  }
}

fs::path scratch() {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("export_exr_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Exports file/name, reads the image back and compares it with the table.
void check_export(const std::string& file, const std::string& name, bool float32) {
  INFO(name);
  const fs::path tables = fs::path(BRDFTAB_SOURCE_DIR) / "tables", dir = scratch();
  const auto r = run_cli("export '" + (tables / file).string() + "' " + name + " --format exr --out '" + dir.string() + "'");
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, name + ".exr"));
  CHECK(contains(r.err, "rounded to float32") == !float32);
  const auto lt = brdftab::lookup::load_table(tables / file, name);
  const auto& t = lt.table;
  ExrImage img;
  read_exr(dir / (name + ".exr"), img);
  const int rank = t.rank();
  REQUIRE(img.channels == std::vector<std::string>{"Y"});
  CHECK(img.width == t.axis(rank - 1).n);
  CHECK(img.height == (rank == 2 ? t.axis(0).n : 1));
  std::size_t mismatches = 0, exact_as_double = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::vector<int> idx = rank == 2 ? std::vector<int>{y, x} : std::vector<int>{x};
      const double v = t.at_index(idx);
      const float got = img.pixels[static_cast<std::size_t>(y) * img.width + x];
      const float want = static_cast<float>(v);
      mismatches += std::memcmp(&got, &want, sizeof got) != 0;
      exact_as_double += static_cast<double>(got) == v;
    }
  CHECK(mismatches == 0);
  // A float32 table is held exactly; a float64 one only after rounding (most values differ).
  if (float32) CHECK(exact_as_double == img.pixels.size());
  else CHECK(exact_as_double < img.pixels.size() / 2);
  CHECK(img.str("brdftab.dataset") == name);
  CHECK(img.str("brdftab.source_file") == file);
  CHECK(img.str("brdftab.quantity") == lt.info.attribute_string("quantity"));
  CHECK(img.str("brdftab.interpolation") == std::string(brdftab::lookup::interpolation_name(t.interpolation())));
  CHECK(img.integer("brdftab.rank") == rank);
  for (int d = 0; d < rank; ++d) {
    const auto& a = t.axis(d);
    const std::string p = "brdftab.axis" + std::to_string(d) + ".";
    CHECK(img.str(p + "name") == a.name);
    CHECK(img.str(p + "units") == a.units);
    CHECK(img.str(p + "transform") == std::string(brdftab::lookup::transform_name(a.transform)));
    CHECK(img.str(p + "image_axis") == (d == rank - 1 ? "x" : "y"));
    CHECK(img.integer(p + "n") == a.n);
    CHECK(img.num(p + "scale") == a.scale);
    CHECK(img.num(p + "u_first") == a.u0);
    CHECK(img.num(p + "u_step") == a.du);
    CHECK(img.num(p + "x_lo") == a.x_lo);
    CHECK(img.num(p + "x_hi") == a.x_hi);
    // The grid in physical units follows from the attributes alone: the last node is x_hi.
    CHECK(a.value(a.n - 1) == a.x_hi);
  }
  CHECK(img.num("brdftab.attr.max_abs_error") == lt.info.attribute_number("max_abs_error", NAN));
}

}  // namespace

TEST_CASE("export --format exr holds a 2-D compact table's float32 values and axis metadata exactly") {
  check_export("smith_gbeckmann.h5", "smith_gbeckmann_g1_compact", true);
  check_export("hfunc.h5", "hfunc_ls1_compact", true);
}

TEST_CASE("export --format exr writes a 1-D table as one row, a float64 table rounded to float32 with a note") {
  check_export("fresnel.h5", "fresnel_dr", false);
}

TEST_CASE("export --format exr refuses a 3-D table with exit 2 naming the rank") {
  const fs::path dir = scratch();
  const auto r = run_cli("export '" + (fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "ghs_sigma_rel.h5").string() +
                         "' ghs_sigma_rel2_grid --format exr --out '" + dir.string() + "'");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "rank 3"));
  CHECK(contains(r.err, "OpenEXR export covers 1-D and 2-D tables"));
  // Nothing written but the folder's writer lock (docs/reliability.md).
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename() == ".brdftab.lock");
}
