#include "lookup/table_set.hpp"

#include <algorithm>
#include <sstream>

#include "lookup/bounded_read.hpp"

namespace brdftab::lookup {

TableSet::TableSet(std::filesystem::path dir, OpenOptions options) : dir_(std::move(dir)), options_(options) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec))
    throw TableFileError("table folder '" + dir_.string() + "' does not exist or is not a directory");
  // A scene folder: the "file NAME KEY" lines at the head of scene.index (before the first
  // material). Read with the index's cap; a folder without an index has no expectations.
  const auto index = dir_ / "scene.index";
  if (std::filesystem::exists(index, ec)) {
    std::string text;
    try {
      text = read_regular_file(index, std::size_t(64) << 20, "scene index");
    } catch (const InputFileError& e) {
      throw TableFileError(std::string("table folder '") + dir_.string() + "': " + e.what());
    }
    std::istringstream in(text);
    std::string line, line1;
    std::getline(in, line1);
    if (line1 == "brdftab-scene-index 1")
      while (std::getline(in, line) && line.rfind("material ", 0) != 0) {
        std::istringstream ls(line);
        std::string word, file, key;
        if (ls >> word >> file >> key && word == "file") expected_keys_[file] = key;
      }
  }
}

void TableSet::expect_content_keys(std::map<std::string, std::string> keys) {
  std::lock_guard lock(mutex_);
  expected_keys_ = std::move(keys);
}

const LoadedTable& TableSet::get(const std::string& file, const std::string& dataset) {
  const std::string key = file + "\n" + dataset;
  std::lock_guard lock(mutex_);
  auto it = loaded_.find(key);
  if (it != loaded_.end()) return *it->second;
  auto f = files_.find(file);
  if (f == files_.end()) {
    VerifiedFile vf = VerifiedFile::open(dir_ / file, options_);
    if (const auto e = expected_keys_.find(file); e != expected_keys_.end()) {
      const auto attrs = vf.attributes();
      const auto a = attrs.find("content_key");
      const std::string* stored = a == attrs.end() ? nullptr : std::get_if<std::string>(&a->second);
      if (!stored || *stored != e->second)
        throw TableFileError("table file '" + (dir_ / file).string() + "' was not written by the run that wrote " +
                             (dir_ / "scene.index").string() + " (its content key " +
                             (stored ? stored->substr(0, 12) + "..." : std::string("(none)")) + ", the index expects " +
                             e->second.substr(0, 12) + "...): the folder mixes two runs; run `brdftab generate` "
                             "again into it");
    }
    f = files_.emplace(file, std::move(vf)).first;
  }
  auto loaded = std::make_unique<LoadedTable>(f->second.load_table(dataset));
  if (!substitute_.empty() && substitute_ == dataset) substituted_ = true;  // NAME is the default table itself
  if (!substitute_.empty() && substitute_ != dataset) {
    const auto names = f->second.list_tables();
    if (std::find(names.begin(), names.end(), substitute_) != names.end()) {
      auto chosen = std::make_unique<LoadedTable>(f->second.load_table(substitute_));
      auto axes = [](const Table& t) {
        std::string s;
        for (int d = 0; d < t.rank(); ++d) s += (d ? ", " : "") + t.axis(d).name;
        return s;
      };
      // NAME stands in only for a request of its kind; a lookup that reads several tables of
      // the file (E_corr, E_sep, ... of one NDF) has NAME answer the one it matches, the
      // others keep their default tables. A request NAME cannot stand in for is remembered:
      // if NAME answers none, refusal() says why.
      std::string why;
      if (axes(chosen->table) != axes(loaded->table))
        why = "table file '" + (dir_ / file).string() + "': dataset '" + substitute_ + "' has axes (" +
              axes(chosen->table) + "), but this lookup reads '" + dataset + "' with axes (" + axes(loaded->table) + ")";
      else if (chosen->info.attribute_string("quantity") != loaded->info.attribute_string("quantity"))
        why = "table file '" + (dir_ / file).string() + "': dataset '" + substitute_ + "' holds \"" +
              chosen->info.attribute_string("quantity").substr(0, 100) + "\", but this lookup reads '" + dataset +
              "' holding \"" + loaded->info.attribute_string("quantity").substr(0, 100) + "\"";
      if (!why.empty()) {
        if (refusal_.empty()) refusal_ = why;
        return *loaded_.emplace(key, std::move(loaded)).first->second;
      }
      loaded = std::move(chosen);
      substituted_ = true;
    }
  }
  return *loaded_.emplace(key, std::move(loaded)).first->second;
}

void TableSet::substitute(std::string dataset) {
  std::lock_guard lock(mutex_);
  substitute_ = std::move(dataset);
}

bool TableSet::substituted() const {
  std::lock_guard lock(mutex_);
  return substituted_;
}

std::string TableSet::refusal() const {
  std::lock_guard lock(mutex_);
  return refusal_;
}

std::size_t TableSet::loaded_count() const {
  std::lock_guard lock(mutex_);
  return loaded_.size();
}

}  // namespace brdftab::lookup
