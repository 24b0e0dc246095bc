// Golden cases as data (docs/testing.md, "Golden cases"): each folder
// tests/golden/<case>/ holds a case.json (the ris commands to run, with their
// inputs) and an expected.json (what every product in the output folder must
// hold). One parameterised test per case runs the commands into a temporary
// folder and compares every file it finds there with expected.json:
//
//   raster (GeoTIFF, PNG)  size, geotransform, no-data and description per
//                          band; integer bands by a hash of their decoded
//                          pixels (exact), float bands by statistics (count,
//                          NaNs, min, max, mean, standard deviation) within
//                          case.json's relative tolerance, their hash kept for
//                          RIS_GOLDEN_EXACT=1
//   JSON                   every leaf: numbers within the tolerance, the rest
//                          exact (paths written as {root}, {tmp} and {out})
//   anything else          a hash of its bytes
//
// A step may also be a command that must fail (exit status and key words
// of its message, see run_step). A file that appears or disappears fails too. With
// RIS_GOLDEN_UPDATE=1 the test writes expected.json instead of comparing
// (scripts/golden-update.sh), so a deliberate change of output shows as a diff in review.
#include <fmt/format.h>
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kRoot = ris::test::source_dir();
const fs::path kGoldenDir = kRoot / "tests" / "golden";

bool env_set(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && std::string(v) == "1";
}

// FNV-1a, 64 bits: detects any change of the bytes (not a security hash).
std::string fnv1a64(const void* data, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 0x100000001b3ULL;
  }
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) {
    s.replace(p, from.size(), to);
  }
  return s;
}

struct Paths {
  std::string root, tmp, out;
  // {root}, {data}, {tmp}, {out} in a case's argument.
  std::string expand(std::string arg) const {
    arg = replace_all(arg, "{data}", root + "/data");
    arg = replace_all(arg, "{root}", root);
    arg = replace_all(arg, "{tmp}", tmp);
    return replace_all(arg, "{out}", out);
  }
  // The inverse, for text written into products (metadata's input paths).
  std::string normalise(std::string s) const {
    s = replace_all(s, out, "{out}");
    s = replace_all(s, tmp, "{tmp}");
    return replace_all(s, root, "{root}");
  }
};

std::string shell_quote(const std::string& s) {
  return "'" + replace_all(s, "'", "'\\''") + "'";
}

// Per band: the decoded pixels in their own type, hashed; statistics over the
// finite values.
json describe_band(GDALRasterBand& band) {
  const int w = band.GetXSize(), h = band.GetYSize();
  const GDALDataType type = band.GetRasterDataType();
  const int bytes = GDALGetDataTypeSizeBytes(type);
  std::vector<unsigned char> buf(std::size_t(w) * std::size_t(h) * std::size_t(bytes));
  if (band.RasterIO(GF_Read, 0, 0, w, h, buf.data(), w, h, type, 0, 0) != CE_None) {
    throw std::runtime_error("cannot read a band");
  }
  std::vector<double> values(std::size_t(w) * std::size_t(h));
  GDALCopyWords64(buf.data(), type, bytes, values.data(), GDT_Float64, 8,
                  static_cast<GPtrDiff_t>(values.size()));
  std::int64_t finite = 0, nan = 0;
  double lo = INFINITY, hi = -INFINITY, sum = 0.0;
  // The count of each value, kept while there are few (categories, masks).
  std::map<double, std::int64_t> counts;
  constexpr std::size_t kMaxDistinct = 64;
  for (const double v : values) {
    if (!std::isfinite(v)) {
      ++nan;
      continue;
    }
    ++finite;
    if (counts.size() <= kMaxDistinct) ++counts[v];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  const double mean = finite > 0 ? sum / double(finite) : 0.0;
  double ss = 0.0;
  for (const double v : values) {
    if (std::isfinite(v)) ss += (v - mean) * (v - mean);
  }
  json b;
  b["type"] = GDALGetDataTypeName(type);
  b["hash"] = fnv1a64(buf.data(), buf.size());
  b["description"] = band.GetDescription();
  int has_nodata = 0;
  const double nodata = band.GetNoDataValue(&has_nodata);
  b["nodata"] = has_nodata ? json(std::isnan(nodata) ? "nan" : std::to_string(nodata)) : json();
  b["finite"] = finite;
  b["non_finite"] = nan;
  b["min"] = finite > 0 ? lo : 0.0;
  b["max"] = finite > 0 ? hi : 0.0;
  b["mean"] = mean;
  b["std"] = finite > 0 ? std::sqrt(ss / double(finite)) : 0.0;
  if (counts.size() <= kMaxDistinct) {
    json c = json::object();
    for (const auto& [v, n] : counts) c[fmt::format("{:.9g}", v)] = n;
    b["value_counts"] = c;
  }
  return b;
}

json describe_raster(const fs::path& p) {
  static const bool registered = [] {
    GDALAllRegister();
    return true;
  }();
  (void)registered;
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(p.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) throw std::runtime_error("GDAL cannot open " + p.string());
  json r;
  r["kind"] = "raster";
  r["width"] = ds->GetRasterXSize();
  r["height"] = ds->GetRasterYSize();
  double gt[6];
  if (ds->GetGeoTransform(gt) == CE_None) r["geotransform"] = std::vector<double>(gt, gt + 6);
  const OGRSpatialReference* srs = ds->GetSpatialRef();
  if (srs != nullptr) {
    const char* name = srs->GetName();
    r["crs"] = name != nullptr ? name : "?";
  }
  json bands = json::array();
  for (int i = 1; i <= ds->GetRasterCount(); ++i)
    bands.push_back(describe_band(*ds->GetRasterBand(i)));
  r["bands"] = bands;
  return r;
}

// JSON flattened to path -> leaf, paths normalised.
void flatten(const json& j, const std::string& prefix, const Paths& paths, json& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix + "/" + k, paths, out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      flatten(j[i], prefix + "/" + std::to_string(i), paths, out);
  } else if (j.is_string()) {
    out[prefix] = paths.normalise(j.get<std::string>());
  } else {
    out[prefix] = j;
  }
}

json describe_file(const fs::path& p, const Paths& paths) {
  const std::string ext = p.extension().string();
  if (ext == ".tif" || ext == ".png") return describe_raster(p);
  const std::string bytes = test::read_file(p);
  if (ext == ".json") {
    json leaves = json::object();
    flatten(json::parse(bytes), "", paths, leaves);
    return json{{"kind", "json"}, {"leaves", leaves}};
  }
  const std::string text = paths.normalise(bytes);
  return json{
      {"kind", "bytes"}, {"size", text.size()}, {"hash", fnv1a64(text.data(), text.size())}};
}

bool near(double a, double b, double rel) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::abs(a - b) <= rel * std::max({std::abs(a), std::abs(b), 1e-300});
}

// Compares two leaves: numbers within `rel`, anything else equal.
void expect_leaf(const json& want, const json& got, double rel, const std::string& where) {
  if (want.is_number() && got.is_number()) {
    EXPECT_TRUE(near(want.get<double>(), got.get<double>(), rel))
        << where << ": expected " << want << ", got " << got << " (relative tolerance " << rel
        << ")";
  } else {
    EXPECT_EQ(want, got) << where;
  }
}

void compare_file(const json& want, const json& got, double rel, bool exact,
                  const std::string& name) {
  ASSERT_EQ(want.value("kind", ""), got.value("kind", "")) << name;
  const std::string kind = got["kind"];
  if (kind == "bytes") {
    EXPECT_EQ(want, got) << name << ": bytes changed";
  } else if (kind == "json") {
    const json& w = want["leaves"];
    const json& g = got["leaves"];
    for (const auto& [k, v] : w.items()) {
      if (!g.contains(k)) {
        ADD_FAILURE() << name << k << ": missing";
        continue;
      }
      expect_leaf(v, g[k], rel, name + k);
    }
    for (const auto& [k, v] : g.items()) {
      if (!w.contains(k)) ADD_FAILURE() << name << k << ": new key (value " << v << ")";
    }
  } else {
    for (const char* key : {"width", "height", "crs"}) {
      EXPECT_EQ(want.value(key, json()), got.value(key, json())) << name << " " << key;
    }
    const json wg = want.value("geotransform", json()), gg = got.value("geotransform", json());
    ASSERT_EQ(wg.size(), gg.size()) << name << " geotransform";
    for (std::size_t i = 0; i < wg.size(); ++i) {
      expect_leaf(wg[i], gg[i], 1e-12, name + " geotransform");
    }
    ASSERT_EQ(want["bands"].size(), got["bands"].size()) << name << " band count";
    for (std::size_t i = 0; i < got["bands"].size(); ++i) {
      const json& w = want["bands"][i];
      const json& g = got["bands"][i];
      const std::string at = name + " band " + std::to_string(i + 1);
      for (const char* key :
           {"type", "description", "nodata", "finite", "non_finite", "value_counts"}) {
        EXPECT_EQ(w.value(key, json()), g.value(key, json())) << at << " " << key;
      }
      const bool is_float = g["type"].get<std::string>().rfind("Float", 0) == 0 ||
                            g["type"].get<std::string>().rfind("CFloat", 0) == 0;
      if (!is_float || exact) {
        EXPECT_EQ(w["hash"], g["hash"]) << at << ": decoded pixels changed";
      }
      for (const char* key : {"min", "max", "mean", "std"}) {
        expect_leaf(w[key], g[key], is_float ? rel : 1e-12, at + " " + key);
      }
    }
  }
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  if (!fs::is_directory(kGoldenDir)) return names;
  for (const auto& e : fs::directory_iterator(kGoldenDir)) {
    if (fs::exists(e.path() / "case.json")) names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// One step of a case: an array of arguments, which must succeed, or an
// object {"args": [...], "env": {"VAR": "value"}, "expect_failure":
// {"exit_status": N, "message_has": ["key word", ...]}} (PROJ's .gie
// `expect failure`): the command must exit with that status and its output
// name every key word. What a failed step leaves is checked with the
// products: nothing the case's expected.json does not list.
void run_step(const json& step, const Paths& paths) {
  const json& argv = step.is_array() ? step : step.at("args");
  std::string args, env;
  for (const json& a : argv) args += " " + shell_quote(paths.expand(a.get<std::string>()));
  if (step.is_object() && step.contains("env")) {
    for (const auto& [k, v] : step["env"].items()) {
      env += " " + k + "=" + shell_quote(paths.expand(v.get<std::string>()));
    }
  }
  const test::RunResult r = test::run_ris_env(env, args);
  if (!step.is_object() || !step.contains("expect_failure")) {
    ASSERT_EQ(r.exit_code, 0) << env << " ris" << args << "\n" << r.output;
    return;
  }
  const json& want = step["expect_failure"];
  EXPECT_EQ(r.exit_code, want.at("exit_status").get<int>()) << env << " ris" << args << "\n"
                                                            << r.output;
  for (const json& word : want.value("message_has", json::array())) {
    EXPECT_NE(r.output.find(paths.expand(word.get<std::string>())), std::string::npos)
        << "the message lacks \"" << word.get<std::string>() << "\": " << r.output;
  }
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, ProductsMatchExpected) {
  const fs::path dir = kGoldenDir / GetParam();
  const json spec = json::parse(test::read_file(dir / "case.json"));
  const double rel = spec.value("float_rel_tolerance", 1e-6);
  test::TempDir tmp;
  Paths paths{kRoot.string(), tmp.path().string(), (tmp.path() / "out").string()};
  fs::create_directories(paths.out);

  // The case's commands, in order.
  for (const json& step : spec.at("steps")) run_step(step, paths);

  // Every file of the output folder, by its path under it.
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(paths.out)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  json got = json::object();
  for (const fs::path& f : files) {
    got[fs::relative(f, paths.out).generic_string()] = describe_file(f, paths);
  }

  const fs::path expected_path = dir / "expected.json";
  if (env_set("RIS_GOLDEN_UPDATE")) {
    std::ofstream(expected_path) << json{{"products", got}}.dump(1) << "\n";
    GTEST_SKIP() << "wrote " << expected_path;
  }
  ASSERT_TRUE(fs::exists(expected_path))
      << expected_path << " is missing: run scripts/golden-update.sh and review the diff";
  const json want = json::parse(test::read_file(expected_path)).at("products");
  const bool exact = env_set("RIS_GOLDEN_EXACT");
  for (const auto& [name, w] : want.items()) {
    if (!got.contains(name)) {
      ADD_FAILURE() << name << ": expected product not written";
      continue;
    }
    compare_file(w, got[name], rel, exact, name);
  }
  for (const auto& [name, g] : got.items()) {
    if (!want.contains(name)) ADD_FAILURE() << name << ": new product, not in expected.json";
  }
}

// gtest names allow letters, digits and '_' only.
std::string case_test_name(const ::testing::TestParamInfo<std::string>& p) {
  std::string n = p.param;
  std::replace(n.begin(), n.end(), '-', '_');
  return n;
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(case_names()), case_test_name);

}  // namespace
}  // namespace ris
