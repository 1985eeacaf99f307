// file: docs/examples/table_set.cpp
// Any table through lookup::TableSet: scalar, checked and batched queries.
#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/table_set.hpp>
#include <cstdio>
#include <vector>
int main() {
  brdftab::lookup::TableSet tables(brdftab::lookup::default_tables_dir());  // touches no file yet
  const auto& T = tables.table("demo.h5", "demo_exp_cos");  // loads and validates on first use
  double v = T(0.8, 0.6);                                   // scalar, clamps out-of-range input
  double w = T.eval2(0.8, 0.6, brdftab::lookup::OutOfDomain::error);  // or throws DomainError
  std::vector<double> points = {0.8, 0.6, 0.1, 0.2}, out(2);  // n x rank, point-major
  T.eval_batch(points, out);                                   // n values
  std::printf("%.9f %.9f %.9f %.9f\n", v, w, out[0], out[1]);
}
