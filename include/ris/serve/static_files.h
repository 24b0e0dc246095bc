// The page's files (HTML, CSS, JS), read once at start-up from one folder
// into memory and served by name. A request names a file; it is looked up
// in that table and never turned into a path, so no request can make the
// server open a file (`../../etc/passwd`, `%2e%2e/`, absolute paths: all
// simply not found).
//
// Example:
//   ris::StaticFiles files(ris::data_dir() / "serve");
//   if (const ris::StaticFile* f = files.find("index.html")) send(f->content, f->mime);
//   files.add_optional("vendor/leaflet/leaflet.js", "/usr/share/javascript/leaflet/leaflet.js");
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace ris {

struct StaticFile {
  std::string content;
  std::string mime;  // from the extension: text/html, text/css, ...
};

class StaticFiles {
 public:
  // Reads every regular file directly in `folder` (not its subfolders).
  // Throws InputError when the folder has no index.html.
  explicit StaticFiles(const std::filesystem::path& folder);
  // The file of that name ("" means index.html), or nullptr.
  const StaticFile* find(const std::string& name) const;
  // Reads `path` (when it is a regular file) into the table under `name`,
  // e.g. "vendor/leaflet/leaflet.js"; false when it is missing.
  bool add_optional(const std::string& name, const std::filesystem::path& path);

 private:
  std::map<std::string, StaticFile> files_;
};

}  // namespace ris
