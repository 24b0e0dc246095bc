// Issue 37, item 5: every value read from a NISAR (HDF5) or Sentinel-1 (XML
// annotation) product is checked where it is read. Each test damages a copy
// of a shipped real product in a temporary folder (a NaN, an infinity, a
// zero, a negative, an absurd size) and expects a refusal that names the
// file and the dataset or XML element; a Sentinel-1 GRD annotation is refused
// naming productType; a huge declared dataset is refused before any big
// allocation; a FIFO acquisition and a NaN --point are refused.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "acquisition_paths.h"
#include "hdf5_edit.h"
#include "ris/io/intensity_image.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/sentinel1_annotation.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// `read` throws an InputError naming `file` and a key containing `key`
// (the dataset path or XML element); returns its message.
std::string expect_refused(const std::function<void()>& read, const fs::path& file,
                           const std::string& key) {
  try {
    read();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string()) << e.what();
    EXPECT_NE(e.key().find(key), std::string::npos) << "key '" << e.key() << "': " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted a damaged " << key << " in " << file;
  return "";
}

// --- Sentinel-1 annotation -------------------------------------------------

// One change to the annotation: the text of the first <tag> element after
// the first occurrence of `after` (an opening tag, or any unique text).
struct XmlEdit {
  std::string after, tag, value;
};

fs::path annotation_xml() {
  for (const auto& e : fs::directory_iterator(fs::path(test::sentinel1_safe()) / "annotation")) {
    if (e.path().extension() == ".xml") return e.path();
  }
  return {};
}

// A copy of the shipped IW SLC annotation in dir with the edits made.
fs::path damaged_annotation(const test::TempDir& dir, const std::vector<XmlEdit>& edits) {
  std::string xml = test::read_file(annotation_xml());
  for (const XmlEdit& e : edits) {
    const auto from = xml.find(e.after);
    const auto open = xml.find("<" + e.tag + ">", from);
    const auto close = xml.find("</" + e.tag + ">", open);
    if (from == std::string::npos || open == std::string::npos || close == std::string::npos) {
      ADD_FAILURE() << "no <" << e.tag << "> after " << e.after;
      continue;
    }
    const auto start = open + e.tag.size() + 2;
    xml.replace(start, close - start, e.value);
  }
  const fs::path out = dir / "s1a-iw1-slc-vv-damaged.xml";
  test::write_file(out, xml);
  return out;
}

// The annotation with one element set to each of `values`: each refused
// naming `key`.
void expect_each_refused(const std::string& after, const std::string& tag,
                         const std::vector<std::string>& values, const std::string& key) {
  for (const std::string& v : values) {
    SCOPED_TRACE(tag + " = " + v);
    test::TempDir dir;
    const fs::path xml = damaged_annotation(dir, {{after, tag, v}});
    expect_refused([&] { read_acquisition(xml); }, xml, key);
  }
}

TEST(AcquisitionHardening, UndamagedAnnotationCopyReadsAsTheOriginal) {
  test::TempDir dir;
  const fs::path xml = damaged_annotation(dir, {});
  const Acquisition copy = read_acquisition(xml);
  const Acquisition original = read_acquisition(test::sentinel1_safe());
  EXPECT_EQ(copy.grid.lines, original.grid.lines);
  EXPECT_EQ(copy.grid.bins, original.grid.bins);
  EXPECT_DOUBLE_EQ(copy.grid.range_spacing_m, original.grid.range_spacing_m);
}

TEST(AcquisitionHardening, Sentinel1RangeAndTimingElementsChecked) {
  const std::string info = "imageAnnotation.imageInformation.";
  expect_each_refused("<productInformation>", "rangeSamplingRate",
                      {"0", "-6.434523812571428e+07", "nan", "inf", "1e300"},
                      "generalAnnotation.productInformation.rangeSamplingRate");
  expect_each_refused("<imageInformation>", "azimuthTimeInterval",
                      {"-2.055556299999998e-03", "0", "nan", "-inf", "20"},
                      info + "azimuthTimeInterval");
  expect_each_refused("<imageInformation>", "slantRangeTime", {"0", "-5.3e-03", "inf", "1"},
                      info + "slantRangeTime");
  expect_each_refused("<imageInformation>", "numberOfSamples", {"0", "-22694", "3e9", "22694.5"},
                      info + "numberOfSamples");
  expect_each_refused("<productInformation>", "radarFrequency", {"0", "-5.4e9", "1e15", "nan"},
                      "generalAnnotation.productInformation.radarFrequency");
  expect_each_refused("<downlinkInformation>", "prf", {"0", "-1717", "inf"},
                      "downlinkInformation.prf");
  expect_each_refused("<processingInformation>", "ellipsoidSemiMajorAxis", {"0", "nan", "6.4e8"},
                      "ellipsoidSemiMajorAxis");
}

TEST(AcquisitionHardening, Sentinel1BurstElementsChecked) {
  expect_each_refused("<swathTiming>", "linesPerBurst", {"0", "-1501", "1501.5", "1e12", "nan"},
                      "swathTiming.linesPerBurst");
  // The second burst's time before the first's: not increasing.
  test::TempDir dir;
  const fs::path xml =
      damaged_annotation(dir, {{"</burst>", "azimuthTime", "2022-01-04T17:05:50.000000"}});
  const std::string m = expect_refused([&] { read_acquisition(xml); }, xml,
                                       "swathTiming.burstList.burst.azimuthTime");
  EXPECT_NE(m.find("strictly increasing"), std::string::npos) << m;
}

// The annotation as a stripmap product: no bursts, linesPerBurst 0 (as
// ESA's stripmap annotations give it), numberOfLines set to `lines`.
fs::path stripmap_annotation(const test::TempDir& dir, const std::string& lines) {
  const fs::path xml = damaged_annotation(dir, {{"<swathTiming>", "linesPerBurst", "0"},
                                                {"<imageInformation>", "numberOfLines", lines}});
  std::string text = test::read_file(xml);
  const auto open = text.find("<burstList count=");
  const std::string end = "</burstList>";
  const auto close = text.find(end, open);
  EXPECT_NE(close, std::string::npos);
  text.replace(open, close + end.size() - open, "<burstList count=\"0\"></burstList>");
  test::write_file(xml, text);
  return xml;
}

TEST(AcquisitionHardening, Sentinel1StripmapReadsFromTheFirstLineTime) {
  test::TempDir dir;
  const fs::path xml = stripmap_annotation(dir, "13509");
  const Acquisition a = read_acquisition(xml);
  EXPECT_EQ(a.grid.lines, 13509);  // numberOfLines
  // productFirstLineUtcTime, 17:05:58.268589, against midnight.
  EXPECT_NEAR(a.grid.sensing_start_s, 17 * 3600.0 + 5 * 60.0 + 58.268589, 1e-6);
  for (const char* bad : {"0", "-3", "1e300", "nan"}) {
    SCOPED_TRACE(bad);
    test::TempDir d;
    const fs::path b = stripmap_annotation(d, bad);
    expect_refused([&] { read_acquisition(b); }, b,
                   "imageAnnotation.imageInformation.numberOfLines");
  }
}

TEST(AcquisitionHardening, Sentinel1StateVectorsChecked) {
  const std::string orbit = "generalAnnotation.orbitList.orbit.";
  for (const char* v : {"nan", "inf"}) {
    test::TempDir dir;
    const fs::path xml = damaged_annotation(dir, {{"<velocity>", "y", v}});
    expect_refused([&] { read_acquisition(xml); }, xml, "velocity.y");
  }
  {  // A zero position, a zero velocity, one at 10^6 km.
    test::TempDir dir;
    const fs::path xml = damaged_annotation(
        dir, {{"<position>", "x", "0"}, {"<position>", "y", "0"}, {"<position>", "z", "0"}});
    const std::string m = expect_refused([&] { read_acquisition(xml); }, xml, orbit + "position");
    EXPECT_NE(m.find("state vector 0"), std::string::npos) << m;
  }
  {
    test::TempDir dir;
    const fs::path xml = damaged_annotation(
        dir, {{"<velocity>", "x", "0"}, {"<velocity>", "y", "0"}, {"<velocity>", "z", "0"}});
    expect_refused([&] { read_acquisition(xml); }, xml, orbit + "velocity");
  }
  {
    test::TempDir dir;
    const fs::path xml = damaged_annotation(dir, {{"</orbit>", "x", "1e9"}});
    const std::string m = expect_refused([&] { read_acquisition(xml); }, xml, orbit + "position");
    EXPECT_NE(m.find("state vector 1"), std::string::npos) << m;
  }
}

TEST(AcquisitionHardening, Sentinel1GrdRefusedNamingTheProductType) {
  test::TempDir dir;
  const fs::path grd =
      damaged_annotation(dir, {{"<adsHeader>", "productType", "GRD"},
                               {"<productInformation>", "projection", "Ground Range"}});
  const std::string m =
      expect_refused([&] { read_acquisition(grd); }, grd, "adsHeader.productType");
  EXPECT_NE(m.find("GRD"), std::string::npos) << m;
  EXPECT_NE(m.find("Ground Range"), std::string::npos) << m;
  // An "SLC" whose image is on ground range is no SLC either.
  test::TempDir dir2;
  const fs::path ground =
      damaged_annotation(dir2, {{"<productInformation>", "projection", "Ground Range"}});
  expect_refused([&] { read_acquisition(ground); }, ground,
                 "generalAnnotation.productInformation.projection");
}

TEST(AcquisitionHardening, Sentinel1TiePointsChecked) {
  test::TempDir dir;
  const fs::path xml = damaged_annotation(dir, {{"<geolocationGridPoint>", "latitude", "95"}});
  expect_refused([&] { read_sentinel1_tie_points(xml); }, xml, "latitude");
  test::TempDir dir2;
  const fs::path line = damaged_annotation(dir2, {{"<geolocationGridPoint>", "line", "3e9"}});
  expect_refused([&] { read_sentinel1_tie_points(line); }, line, "line");
}

// --- NISAR RSLC (HDF5) -----------------------------------------------------

const std::string kSlc = "/science/LSAR/SLC";
const std::string kFreqA = kSlc + "/swaths/frequencyA";

// A copy of winnipeg.h5 in dir (4 MB).
fs::path product_copy(const test::TempDir& dir) {
  const fs::path out = dir / "winnipeg-damaged.h5";
  fs::copy_file(test::winnipeg_h5(), out);
  return out;
}

// The product with one element of `dataset` (at `coord`) set to each of
// `values`: each refused naming the dataset.
void expect_each_refused_h5(const std::string& dataset, const std::vector<hsize_t>& coord,
                            const std::vector<double>& values) {
  for (double v : values) {
    SCOPED_TRACE(dataset + " = " + std::to_string(v));
    test::TempDir dir;
    const fs::path h5 = product_copy(dir);
    test::h5_set(h5, dataset, coord, v);
    expect_refused([&] { read_acquisition(h5); }, h5, dataset);
  }
}

TEST(AcquisitionHardening, UndamagedProductCopyReadsAsTheOriginal) {
  test::TempDir dir;
  const fs::path h5 = product_copy(dir);
  // Rewriting a value with itself goes through the helper without damage.
  test::h5_set(h5, kFreqA + "/slantRangeSpacing", {}, 6.245676208);
  const Acquisition a = read_acquisition(h5);
  EXPECT_DOUBLE_EQ(a.grid.range_spacing_m, 6.245676208);
  EXPECT_EQ(a.grid.bins, 250);
}

TEST(AcquisitionHardening, NisarGridDatasetsChecked) {
  expect_each_refused_h5(kFreqA + "/slantRange", {3}, {kNaN, kInf, -1.0, 100.0});
  expect_each_refused_h5(kFreqA + "/slantRange", {0}, {kNaN, -13150.0, 1e12});
  expect_each_refused_h5(kFreqA + "/slantRangeSpacing", {}, {0.0, -6.2, kNaN, 1e6});
  expect_each_refused_h5(kFreqA + "/processedCenterFrequency", {}, {0.0, -1.243e9, kInf, 1e15});
  expect_each_refused_h5(kFreqA + "/nominalAcquisitionPRF", {}, {0.0, -36.6, kNaN});
  expect_each_refused_h5(kSlc + "/swaths/zeroDopplerTimeSpacing", {}, {0.0, -0.027, kNaN, 1e9});
  expect_each_refused_h5(kSlc + "/swaths/zeroDopplerTime", {0}, {kNaN, 1e12, -kInf});
  expect_each_refused_h5(kSlc + "/swaths/zeroDopplerTime", {100}, {kNaN, 0.0});
}

TEST(AcquisitionHardening, NisarStateVectorsChecked) {
  const std::string orbit = kSlc + "/metadata/orbit";
  expect_each_refused_h5(orbit + "/velocity", {5, 1}, {kNaN, kInf, 1e5});
  expect_each_refused_h5(orbit + "/position", {2, 0}, {kNaN, -kInf, 1e9});
  expect_each_refused_h5(orbit + "/time", {3}, {kNaN, 1e12});
  // A zero position (all three components), a zero velocity.
  for (const char* what : {"/position", "/velocity"}) {
    test::TempDir dir;
    const fs::path h5 = product_copy(dir);
    for (hsize_t k = 0; k < 3; ++k) test::h5_set(h5, orbit + what, {7, k}, 0.0);
    const std::string m = expect_refused([&] { read_acquisition(h5); }, h5, orbit + what);
    EXPECT_NE(m.find("state vector 7"), std::string::npos) << m;
  }
}

// The peak resident memory of this process so far, bytes.
long peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss * 1024L;
}

TEST(AcquisitionHardening, HugeDeclaredDatasetRefusedBeforeAllocation) {
  test::TempDir dir;
  const fs::path h5 = product_copy(dir);
  // 2e9 doubles declared (16 GB), never written: the file stays small.
  test::h5_replace_with_undeclared(h5, kFreqA + "/slantRange", {2'000'000'000});
  EXPECT_LT(fs::file_size(h5), 8u << 20);
  const long before = peak_rss_bytes();
  const std::string m = expect_refused([&] { read_acquisition(h5); }, h5, kFreqA + "/slantRange");
  EXPECT_NE(m.find("declares 2000000000 values"), std::string::npos) << m;
  EXPECT_LT(peak_rss_bytes() - before, 256L << 20);  // no 16 GB asked for
}

TEST(AcquisitionHardening, HugeDeclaredImageRefusedBeforeAllocation) {
  test::TempDir dir;
  const fs::path h5 = product_copy(dir);
  // The HH layer declared 100,000 x 100,000 complex pixels (80 GB).
  test::h5_replace_with_undeclared(h5, kFreqA + "/HH", {100'000, 100'000});
  const long before = peak_rss_bytes();
  try {
    read_intensity_image(h5.string(), 1, PixelScale::automatic);
    ADD_FAILURE() << "a 10^10-pixel image was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), h5.string());
    EXPECT_NE(e.key().find("frequencyA/HH"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("100000 x 100000"), std::string::npos) << e.what();
  }
  EXPECT_LT(peak_rss_bytes() - before, 256L << 20);
}

// --- Any acquisition: FIFOs, --point -----------------------------------------

// While alive, opens `fifo` for writing whenever a reader is blocked on it,
// so that a reader which opened it (a regression) gets end-of-file and the
// test fails instead of hanging; says whether that happened.
class FifoUnblocker {
 public:
  explicit FifoUnblocker(const fs::path& fifo)
      : thread_([this, fifo] {
          while (!stop_) {
            // Succeeds only when a reader has the FIFO open.
            const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) {
              blocked_ = true;
              ::close(fd);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
          }
        }) {}
  ~FifoUnblocker() {
    stop_ = true;
    thread_.join();
  }
  FifoUnblocker(const FifoUnblocker&) = delete;
  FifoUnblocker& operator=(const FifoUnblocker&) = delete;
  bool reader_blocked() const { return blocked_; }

 private:
  std::atomic<bool> stop_{false}, blocked_{false};
  std::thread thread_;
};

TEST(AcquisitionHardening, FifoAcquisitionRefusedBeforeOpening) {
  test::TempDir dir;
  for (const char* name : {"fifo.h5", "fifo.xml", "fifo.toml"}) {
    SCOPED_TRACE(name);
    const fs::path p = dir / name;
    ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
    const FifoUnblocker unblocker(p);
    // Opening would block until a writer came; refused at once instead.
    try {
      read_acquisition(p);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is a FIFO (named pipe)"), std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(unblocker.reader_blocked()) << "the reader opened the FIFO";
  }
  // The command line too, under a time limit (a regression would block it
  // for good: exit status 124 then).
  const fs::path log = dir / "geo2rdr.txt";
  const std::string cmd = "timeout 20 " + std::string(test::ris_exe()) + " geo2rdr -a " +
                          test::q(dir / "fifo.h5") + " --point 49.45,-97.77,240 > " + test::q(log) +
                          " 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << test::read_file(log);
  EXPECT_NE(test::read_file(log).find("is a FIFO (named pipe); expected a regular file"),
            std::string::npos)
      << test::read_file(log);
}

TEST(AcquisitionHardening, Geo2rdrPointsChecked) {
  const std::string a = "geo2rdr -a " + test::winnipeg_h5();
  for (const char* p :
       {"nan,nan,nan", "inf,-97.77,240", "49.45,-inf,240", "91,-97.77,240", "-90.5,-97.77,240",
        "49.45,-181,240", "49.45,361,240", "49.45,-97.77,1e9", "49.45,-97.77,nan"}) {
    SCOPED_TRACE(p);
    const auto r = test::run_ris(a + " --point " + p);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("--point"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("outside-orbit"), std::string::npos) << r.output;
  }
  EXPECT_EQ(test::run_ris(a + " --point 49.45,-97.77,240").exit_code, 0);
  test::TempDir dir;
  test::write_file(dir / "points.csv", "49.45,-97.77,240\n49.45,nan,240\n");
  const auto csv = test::run_ris(a + " --csv " + test::q(dir / "points.csv"));
  EXPECT_EQ(csv.exit_code, 1) << csv.output;
  EXPECT_NE(csv.output.find("line 2"), std::string::npos) << csv.output;
  const auto pixel =
      test::run_ris("rdr2geo -a " + test::winnipeg_h5() + " --height 0 --pixel nan,3");
  EXPECT_EQ(pixel.exit_code, 1) << pixel.output;
  EXPECT_NE(pixel.output.find("--pixel"), std::string::npos) << pixel.output;
  const auto height =
      test::run_ris("rdr2geo -a " + test::winnipeg_h5() + " --height inf --pixel 3,3");
  EXPECT_EQ(height.exit_code, 1) << height.output;
  EXPECT_NE(height.output.find("--height"), std::string::npos) << height.output;
}

}  // namespace
}  // namespace ris
