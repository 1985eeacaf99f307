// The registry of auditable models, instantiated from numerics/brdf_audit_model_list.hpp.
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/brdf_audit_model_list.hpp"

namespace brdftab::numerics {

#define BRDFTAB_DECLARE_AUDIT_MODELS(K) std::vector<AuditableModel> audit_models_##K();
BRDFTAB_AUDIT_MODELS(BRDFTAB_DECLARE_AUDIT_MODELS)
#undef BRDFTAB_DECLARE_AUDIT_MODELS

const std::vector<AuditableModel>& auditable_models() {
  static const std::vector<AuditableModel> models = [] {
    std::vector<AuditableModel> all;
#define BRDFTAB_APPEND_AUDIT_MODELS(K)                \
  for (auto& m : audit_models_##K()) all.push_back(std::move(m));
    BRDFTAB_AUDIT_MODELS(BRDFTAB_APPEND_AUDIT_MODELS)
#undef BRDFTAB_APPEND_AUDIT_MODELS
    return all;
  }();
  return models;
}

}  // namespace brdftab::numerics
