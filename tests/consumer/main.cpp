// Opens a table folder lazily and evaluates the demo table: exits 0 if the value matches
// the closed form within the table's stated error.
#include <cmath>
#include <cstdio>

#include "lookup/table_set.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer TABLE_DIR\n");
    return 2;
  }
  brdftab::lookup::TableSet tables(argv[1]);
  const auto& loaded = tables.get("demo.h5", "demo_exp_cos");
  const double x = 0.8, y = 0.6;
  const double v = loaded.table(x, y);
  const double err = std::abs(v - std::exp(-x) * std::cos(y));
  const double stated = loaded.info.attribute_number("max_abs_error", 0);
  std::printf("demo_exp_cos(%g, %g) = %.17g, error %.3g, stated max %.3g\n", x, y, v, err, stated);
  return err <= stated ? 0 : 1;
}
