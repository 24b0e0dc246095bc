#include "ris/io/zip_archive.h"

#include <cpl_conv.h>
#include <cpl_vsi.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <string>

#include "ris/util/error.h"

namespace ris {

std::vector<std::uint8_t> zip_files(const std::vector<std::filesystem::path>& files) {
  // A /vsimem/ name of this call's own (callers may run on many threads).
  static std::atomic<std::uint64_t> counter{0};
  const std::string name = "/vsimem/ris-zip-" + std::to_string(counter.fetch_add(1)) + ".zip";
  void* zip = CPLCreateZip(name.c_str(), nullptr);
  RIS_CHECK(zip != nullptr);
  bool ok = true;
  std::string bad;
  for (const std::filesystem::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string content = text.str();
    ok = in.is_open() &&
         CPLCreateFileInZip(zip, f.filename().string().c_str(), nullptr) == CE_None &&
         CPLWriteFileInZip(zip, content.data(), static_cast<int>(content.size())) == CE_None &&
         CPLCloseFileInZip(zip) == CE_None;
    if (!ok) {
      bad = f.string();
      break;
    }
  }
  ok = CPLCloseZip(zip) == CE_None && ok;
  vsi_l_offset length = 0;
  GByte* bytes = VSIGetMemFileBuffer(name.c_str(), &length, TRUE);  // takes ownership
  std::vector<std::uint8_t> out;
  if (bytes != nullptr) out.assign(bytes, bytes + length);
  VSIFree(bytes);
  if (!ok) throw InputError(bad, "", "cannot add the file to the zip archive");
  return out;
}

}  // namespace ris
