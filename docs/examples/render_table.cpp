// file: docs/examples/render_table.cpp
// The render profile of a quantity kept in a compact table (lookup/render_table.hpp): H(c, mu).
#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/render_table.hpp>
#include <cstdio>
#include <vector>

namespace render = brdftab::lookup::render;

int main() {
  brdftab::lookup::TableSet tables(brdftab::lookup::default_tables_dir());
  // Float copy of the table; its float evaluation error is measured here, once.
  const render::FloatTable h = render::float_table_load(tables, "hfunc.h5", "hfunc_iso_compact");
  const double c = 0.9, mu = 0.5;
  const double value = render::eval(h, c, mu);  // arguments in the table's axis order
  std::vector<double> cs{0.5, 0.9}, mus{0.5, 0.5}, out(2);
  render::eval_batch(h, cs, mus, out);          // spans; size mismatch: std::invalid_argument
  std::printf("H(%.1f, %.1f) = %.6f (error <= %.1e, %zu bytes), batch %.6f\n", c, mu, value, h.lookup_error(),
              h.bytes(), out[1]);
}
