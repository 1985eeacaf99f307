#include "lookup/default_tables.hpp"

#include <cstdlib>
#include <system_error>

#if defined(__linux__) || defined(__APPLE__)
#include <dlfcn.h>
#endif

namespace brdftab::lookup {

std::filesystem::path installed_tables_dir() {
  // Relocatable: the tables folder relative to the folder holding this library (a shared
  // libbrdftab_lookup, or the executable it is linked into), so an installation made with
  // `cmake --install --prefix P` or moved elsewhere finds its own tables; else the path
  // configured at build time.
#if (defined(__linux__) || defined(__APPLE__)) && defined(BRDFTAB_TABLES_DIR_FROM_LIBDIR)
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&installed_tables_dir), &info) != 0 && info.dli_fname) {
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::canonical(info.dli_fname, ec);
    if (!ec) {
      const std::filesystem::path dir = (here.parent_path() / BRDFTAB_TABLES_DIR_FROM_LIBDIR).lexically_normal();
      if (std::filesystem::is_directory(dir, ec)) return dir;
    }
  }
#endif
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
