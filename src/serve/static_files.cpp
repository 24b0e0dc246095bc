#include "ris/serve/static_files.h"

#include <fstream>
#include <sstream>

#include "ris/util/error.h"

namespace ris {
namespace {

std::string mime_of(const std::filesystem::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  return "application/octet-stream";
}

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

StaticFiles::StaticFiles(const std::filesystem::path& folder) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    if (!e.is_regular_file()) continue;
    files_[e.path().filename().string()] = StaticFile{read_all(e.path()), mime_of(e.path())};
  }
  if (files_.count("index.html") == 0) {
    throw InputError(folder.string(), "",
                     "the page's folder has no index.html (set RIS_DATA to the data folder)");
  }
}

bool StaticFiles::add_optional(const std::string& name, const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  files_[name] = StaticFile{read_all(path), mime_of(path)};
  return true;
}

const StaticFile* StaticFiles::find(const std::string& name) const {
  const auto it = files_.find(name.empty() ? std::string("index.html") : name);
  return it == files_.end() ? nullptr : &it->second;
}

}  // namespace ris
