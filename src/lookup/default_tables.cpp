#include "lookup/default_tables.hpp"

#include <cstdlib>

namespace brdftab::lookup {

std::filesystem::path installed_tables_dir() {
#ifdef BRDFTAB_INSTALL_TABLES_DIR
  return BRDFTAB_INSTALL_TABLES_DIR;
#else
  return "/usr/local/share/brdftab/tables";
#endif
}

std::filesystem::path default_tables_dir() {
  if (const char* env = std::getenv("BRDFTAB_TABLES"); env && *env) return env;
  return installed_tables_dir();
}

}  // namespace brdftab::lookup
