// `brdftab scene-synth N [--seed S] [--models ghs,ls,...]`: a synthetic scene of N materials
// (JSON on stdout) for measurements (docs/scenes.md). Parameters are drawn from the raw
// output of mt19937_64 (fixed by the C++ standard), so a seed gives the same scene on every
// platform. Models cycle through the list; LS materials are given by c.
#include <cmath>
#include <ostream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "generators/scene_models.hpp"

namespace brdftab::cli {

int run_scene_synth(const SynthOptions& o, std::ostream& out, std::ostream& err) {
  std::vector<std::string> models;
  std::stringstream ss(o.models);
  for (std::string m; std::getline(ss, m, ',');) {
    if (!gen::find_scene_model(m)) {
      err << "brdftab scene-synth: --models: '" << m << "' is not a known model\n";
      return 2;
    }
    models.push_back(m);
  }
  if (models.empty()) {
    err << "brdftab scene-synth: --models is empty\n";
    return 2;
  }
  std::mt19937_64 rng(o.seed);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53); };
  auto round4 = [](double x) { return std::round(x * 1e4) / 1e4; };  // short, exact-in-JSON numbers
  nlohmann::json mats = nlohmann::json::array();
  for (int i = 0; i < o.materials; ++i) {
    const std::string& model = models[static_cast<std::size_t>(i) % models.size()];
    nlohmann::json m = {{"name", model + "_" + std::to_string(i)}, {"model", model}};
    if (model == "ghs" || model == "gbeckmann") {
      m["p"] = round4(u(0.5, 3.0));
      m["beta"] = round4(u(0.05, 0.5));
      if (model == "ghs") {
        m["B"] = round4(std::exp(u(std::log(0.1), std::log(100.0))));
        m["c"] = round4(u(1.5, 6.0));
      }
      m["eta"] = round4(u(1.2, 2.0));
    } else if (model == "ls") {
      m["c"] = round4(u(0.3, 0.999));
    } else {
      m["alpha"] = round4(u(0.05, 0.8));
      m["eta"] = round4(u(1.2, 2.0));
    }
    mats.push_back(m);
  }
  out << nlohmann::json{{"schema_version", 1},
                        {"description", "synthetic scene: " + std::to_string(o.materials) + " materials, seed " +
                                            std::to_string(o.seed)},
                        {"materials", mats}}
             .dump(1)
      << "\n";
  return 0;
}

}  // namespace brdftab::cli
