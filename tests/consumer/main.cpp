// Opens a table folder lazily and evaluates the demo table: exits 0 if the value matches
// the closed form within the table's stated error. Folder: the argument, else the lookup
// library's default (BRDFTAB_TABLES, then the installed tables). Built three ways (CTest):
// against the installed package with find_package, with pkg-config's flags, and in the
// build tree (brdftab::lookup's build-tree include folder): all through <brdftab/...>.
#include <cmath>
#include <cstdio>
#include <cstring>

#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/smith_gbeckmann.hpp>
#include <brdftab/lookup/table_set.hpp>
#include <brdftab/lookup/version.hpp>

int main(int argc, char** argv) {
  if (argc > 2) {
    std::fprintf(stderr, "usage: consumer [TABLE_DIR]\n");
    return 2;
  }
  char version[64];
  std::snprintf(version, sizeof version, "%d.%d.%d", BRDFTAB_VERSION_MAJOR, BRDFTAB_VERSION_MINOR, BRDFTAB_VERSION_PATCH);
  if (std::strcmp(brdftab::kVersion, BRDFTAB_VERSION_STRING) != 0 || std::strcmp(version, brdftab::kVersion) != 0) return 3;
  // A family schema header (standard library only) through the namespaced path too.
  if (brdftab::schema::smith_gbeckmann::kFile != "smith_gbeckmann.h5") return 4;
  brdftab::lookup::TableSet tables(argc == 2 ? std::filesystem::path(argv[1]) : brdftab::lookup::default_tables_dir());
  const auto& loaded = tables.get("demo.h5", "demo_exp_cos");
  const double x = 0.8, y = 0.6;
  const double v = loaded.table(x, y);
  const double err = std::abs(v - std::exp(-x) * std::cos(y));
  const double stated = loaded.info.attribute_number("max_abs_error", 0);
  std::printf("brdftab %s: demo_exp_cos(%g, %g) = %.17g, error %.3g, stated max %.3g (tables %s)\n", brdftab::kVersion,
              x, y, v, err, stated, tables.dir().c_str());
  return err <= stated ? 0 : 1;
}
