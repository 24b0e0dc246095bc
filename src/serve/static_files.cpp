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

}  // namespace

StaticFiles::StaticFiles(const std::filesystem::path& folder) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    files_[e.path().filename().string()] = StaticFile{text.str(), mime_of(e.path())};
  }
  if (files_.count("index.html") == 0) {
    throw InputError(folder.string(), "",
                     "the page's folder has no index.html (set RIS_DATA to the data folder)");
  }
}

const StaticFile* StaticFiles::find(const std::string& name) const {
  const auto it = files_.find(name.empty() ? std::string("index.html") : name);
  return it == files_.end() ? nullptr : &it->second;
}

}  // namespace ris
