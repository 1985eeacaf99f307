#pragma once
// A lazy set of tables: open a folder, load a dataset on first use. A program pays only
// for the tables it touches. get() is thread-safe; the returned reference stays valid for
// the lifetime of the set, and queries on it need no locking. Files are verified as
// load_table does (digest first; foreign files only with options.allow_foreign or
// BRDFTAB_ALLOW_FOREIGN=1). In a scene folder each file must carry the content key
// scene.index lists for it (expect_content_keys). Each file is read and its digest checked once; its bytes
// stay in memory for the lifetime of the set (tables are kilobytes to megabytes).
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "lookup/table_file.hpp"

namespace brdftab::lookup {

class TableSet {
 public:
  // Does not touch the disk until a table is requested. Throws TableFileError if dir is
  // not a directory.
  explicit TableSet(std::filesystem::path dir, OpenOptions options = {});
  const std::filesystem::path& dir() const { return dir_; }
  // Loads <dir>/<file>, dataset `dataset` on first call. Throws TableFileError.
  const LoadedTable& get(const std::string& file, const std::string& dataset);
  const Table& table(const std::string& file, const std::string& dataset) { return get(file, dataset).table; }
  std::size_t loaded_count() const;
  // `eval --dataset NAME`: from now on a request for another table of the file that holds
  // NAME is answered by NAME, provided it has the same axes (names, in order) and the same
  // `quantity` (a compact variant of a precise table, say); a request NAME cannot stand in
  // for gets its own table, and the first such mismatch is kept (refusal(): how they
  // differ). substituted() tells whether NAME answered any request: a caller that needs NAME
  // to answer refuses with refusal() when it did not.
  void substitute(std::string dataset);
  bool substituted() const;
  std::string refusal() const;
  const OpenOptions& options() const { return options_; }
  // The content key each file must carry (file name -> key). A folder written by
  // `generate --scene` lists them in scene.index ("file NAME KEY" lines): the constructor
  // reads them from there, SceneSet passes the ones it parsed. A file whose stored
  // content_key differs was written by another run (a mixed folder): get() throws
  // TableFileError naming it. Files not listed are not checked.
  void expect_content_keys(std::map<std::string, std::string> keys);

 private:
  std::filesystem::path dir_;
  OpenOptions options_;
  mutable std::mutex mutex_;
  std::map<std::string, std::unique_ptr<LoadedTable>> loaded_;
  std::map<std::string, VerifiedFile> files_;  // each file read and verified once
  std::map<std::string, std::string> expected_keys_;
  std::string substitute_;
  bool substituted_ = false;
  std::string refusal_;
};

}  // namespace brdftab::lookup
