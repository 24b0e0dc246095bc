#include "ris/io/file_references.h"

#include <cpl_minixml.h>
#include <cpl_string.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "ris/io/safe_paths.h"
#include "ris/util/error.h"

namespace ris {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxVrtDepth = 8;
constexpr const char* kAllowEnv = "RIS_ALLOW_FILE_REFERENCES";
constexpr const char* kHowToAllow =
    "; if you trust this file, set RIS_ALLOW_FILE_REFERENCES=1 (docs/limits.md)";

// GDAL's own test (VRTDataset::Identify): "<VRTDataset" in the first bytes.
bool looks_like_vrt(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head.find("<VRTDataset") != std::string::npos;
}

// `inner` is `folder` or lies below it (both canonical).
bool is_within(const fs::path& folder, const fs::path& inner) {
  return std::mismatch(folder.begin(), folder.end(), inner.begin(), inner.end()).first ==
         folder.end();
}

fs::path canonical_folder_of(const std::string& path) {
  return fs::weakly_canonical(fs::absolute(path).parent_path());
}

// A file named by `vrt` (or listed for it): a plain path to a regular file
// inside `folder`.
void require_beside(const std::string& vrt, const fs::path& folder, const std::string& name,
                    const fs::path& resolved) {
  if (name.rfind("/vsi", 0) == 0 || name.find("://") != std::string::npos) {
    throw InputError(vrt, "",
                     fmt::format("names \"{}\", a GDAL virtual file system path; ris reads only "
                                 "files beside it{}",
                                 name, kHowToAllow));
  }
  const fs::path canonical = fs::weakly_canonical(resolved);
  if (!is_within(folder, canonical)) {
    throw InputError(vrt, "",
                     fmt::format("names \"{}\" ({}), outside its own folder {}; ris reads only "
                                 "files in the VRT's folder or below it{}",
                                 name, canonical.string(), folder.string(), kHowToAllow));
  }
  require_regular_input(canonical.string(), "");  // not a FIFO, a device or a folder
}

std::string text_of(const CPLXMLNode* node) {
  for (const CPLXMLNode* c = node->psChild; c != nullptr; c = c->psNext) {
    if (c->eType == CXT_Text && c->pszValue != nullptr) return c->pszValue;
  }
  return "";
}

struct XmlCloser {
  void operator()(CPLXMLNode* n) const { CPLDestroyXMLNode(n); }
};

void check_vrt(const std::string& path, int depth);

// One element of a VRT's tree: its rules (the header's list).
void check_vrt_element(const std::string& path, const fs::path& folder, const CPLXMLNode* node,
                       int depth) {
  const std::string element = node->pszValue != nullptr ? node->pszValue : "";
  if (element == "VRTRasterBand" &&
      EQUAL(CPLGetXMLValue(node, "subClass", ""), "VRTRawRasterBand")) {
    throw InputError(path, "",
                     fmt::format("has a raw raster band (VRTRawRasterBand), which reads any "
                                 "file's bytes as pixels; ris does not open such VRTs{}",
                                 kHowToAllow));
  }
  if (element == "PixelFunctionLanguage" && EQUAL(text_of(node).c_str(), "Python")) {
    throw InputError(path, "",
                     fmt::format("has a Python pixel function (code run on reading); ris does "
                                 "not open such VRTs{}",
                                 kHowToAllow));
  }
  if (element != "SourceFilename" && element != "SourceDataset") return;
  const std::string name = text_of(node);
  if (name.empty()) throw InputError(path, "", "has an empty <" + element + ">");
  if (name.rfind("/vsi", 0) != 0 && name.find(':') != std::string::npos) {
    throw InputError(path, "",
                     fmt::format("names \"{}\", a GDAL connection string rather than a file; ris "
                                 "reads only files beside it{}",
                                 name, kHowToAllow));
  }
  const bool relative = EQUAL(CPLGetXMLValue(node, "relativeToVRT", "0"), "1");
  const fs::path resolved = relative ? fs::path(path).parent_path() / name : fs::path(name);
  require_beside(path, folder, name, resolved);
  if (looks_like_vrt(resolved.string())) {
    if (depth + 1 >= kMaxVrtDepth) {
      throw InputError(
          path, "",
          fmt::format("VRTs nest more than {} deep (a VRT naming a VRT ...)", kMaxVrtDepth));
    }
    check_vrt(resolved.string(), depth + 1);
  }
}

void check_vrt(const std::string& path, int depth) {
  const std::unique_ptr<CPLXMLNode, XmlCloser> root(CPLParseXMLFile(path.c_str()));
  if (!root) throw InputError(path, "", "a VRT whose XML cannot be read");
  const fs::path folder = canonical_folder_of(path);
  // Every element, without recursion (the XML may be deep).
  std::vector<const CPLXMLNode*> todo{root.get()};
  while (!todo.empty()) {
    const CPLXMLNode* node = todo.back();
    todo.pop_back();
    for (; node != nullptr; node = node->psNext) {
      if (node->eType != CXT_Element) continue;
      check_vrt_element(path, folder, node, depth);
      if (node->psChild != nullptr) todo.push_back(node->psChild);
    }
  }
}

}  // namespace

bool file_references_allowed() {
  const char* env = std::getenv(kAllowEnv);
  return env != nullptr && *env != '\0' && std::string(env) != "0";
}

void require_safe_vrt_sources(const std::string& path) {
  if (file_references_allowed() || !looks_like_vrt(path)) return;
  check_vrt(path, 0);
}

void require_files_beside(GDALDatasetH ds, const std::string& path) {
  if (file_references_allowed()) return;
  const fs::path folder = canonical_folder_of(path);
  char** files = GDALGetFileList(ds);
  try {
    for (int i = 0; files != nullptr && files[i] != nullptr; ++i) {
      require_beside(path, folder, files[i], fs::path(files[i]));
    }
  } catch (...) {
    CSLDestroy(files);
    throw;
  }
  CSLDestroy(files);
}

}  // namespace ris
