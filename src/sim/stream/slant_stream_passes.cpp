#include "sim/stream/slant_stream_passes.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "ris/image/ground_range.h"
#include "ris/io/compression_preset.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/sim/slar_products.h"
#include "ris/sim/slar_run_setup.h"
#include "sim/engine/block_pass.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// A block of image lines' greytones in slant and ground range (any rank).
struct PictureBlock {
  int k0 = 0, lines = 0;
  std::vector<std::uint8_t> slant, ground;
};

// Pass 2 as a block pass (sim/engine/block_pass.h): the speckled power read
// back block by block, its greytones in slant and ground range
// (render_slar), computed on every rank and written by rank 0 (slant_out,
// ground_out; null on the other ranks) in line order.
class PicturesPass {
 public:
  using Block = PictureBlock;

  PicturesPass(const SlantImagePasses& p, const GreytoneMap& map, const std::string& slant_dir,
               GeoTiffBlockWriter<std::uint8_t>* slant_out,
               GeoTiffBlockWriter<std::uint8_t>* ground_out)
      : p_(p), map_(map), dir_(slant_dir), slant_out_(slant_out), ground_out_(ground_out) {}

  int blocks() const { return (lines() + p_.block_lines - 1) / p_.block_lines; }

  PictureBlock compute(int b) {
    const SlarImage& img = p_.sim.image;
    const GroundRangeGrid& gg = p_.sim.ground_grid;
    // Opened at a rank's first block, so that a rank that cannot read them
    // (an output folder not on a shared file system) fails through the
    // schedule: rank 0 reports it and removes its staging folder.
    if (!sp_ds_) {
      sp_ds_.emplace(open_raster((dir_ / "speckled_power_slant.tif").string()));
      mask_ds_.emplace(open_raster((dir_ / "mask_slant.tif").string()));
    }
    PictureBlock k;
    k.k0 = b * p_.block_lines;
    k.lines = std::min(p_.block_lines, lines() - k.k0);
    const int n = k.lines;
    const std::size_t np = sz(n) * sz(img.bins);
    speckled_.resize(np);
    mask_.resize(np);
    read_rows(handle(*sp_ds_), k.k0, n, speckled_.data(), GDT_Float32, "speckled_power_slant.tif");
    read_rows(handle(*mask_ds_), k.k0, n, mask_.data(), GDT_Byte, "mask_slant.tif");
    no_data_.resize(np);
    for (std::size_t i = 0; i < np; ++i) no_data_[i] = (mask_[i] & pixel_flag::kNoData) ? 1 : 0;
    k.slant.resize(np);
    greytones(speckled_, k.slant, map_, no_data_);
    const std::vector<float> ground_power = to_ground_range(speckled_, n, img.range, gg);
    const std::vector<std::uint8_t> ground_mask =
        to_ground_range_nearest(mask_, n, img.range, gg, pixel_flag::kNoData);
    ground_no_data_.resize(ground_mask.size());
    for (std::size_t i = 0; i < ground_mask.size(); ++i)
      ground_no_data_[i] = (ground_mask[i] & pixel_flag::kNoData) ? 1 : 0;
    k.ground.resize(ground_power.size());
    greytones(ground_power, k.ground, map_, ground_no_data_);
    return k;
  }

  void pack(const PictureBlock& k, std::vector<char>& out) const {
    const std::size_t sizes[4] = {std::size_t(k.k0), std::size_t(k.lines), k.slant.size(),
                                  k.ground.size()};
    const char* h = reinterpret_cast<const char*>(sizes);
    out.insert(out.end(), h, h + sizeof(sizes));
    out.insert(out.end(), k.slant.begin(), k.slant.end());
    out.insert(out.end(), k.ground.begin(), k.ground.end());
  }

  PictureBlock unpack(const char* at, std::size_t n) const {
    std::size_t sizes[4] = {};
    RIS_CHECK(n >= sizeof(sizes));
    std::memcpy(sizes, at, sizeof(sizes));
    RIS_CHECK(n == sizeof(sizes) + sizes[2] + sizes[3]);
    PictureBlock k;
    k.k0 = static_cast<int>(sizes[0]);
    k.lines = static_cast<int>(sizes[1]);
    const char* d = at + sizeof(sizes);
    k.slant.assign(d, d + sizes[2]);
    k.ground.assign(d + sizes[2], d + sizes[2] + sizes[3]);
    return k;
  }

  void consume(int, PictureBlock& k) {
    slant_out_->write(k.slant.data(), k.lines);
    ground_out_->write(k.ground.data(), k.lines);
    // The pass's share of the bar, spread over its lines.
    const std::int64_t n = std::max(lines(), 1);
    p_.bar->advance(p_.bar_units * (k.k0 + k.lines) / n - p_.bar_units * k.k0 / n);
  }

  void release() {
    sp_ds_.reset();
    mask_ds_.reset();
  }

 private:
  int lines() const { return p_.sim.image.lines; }

  const SlantImagePasses& p_;
  const GreytoneMap& map_;
  const std::filesystem::path dir_;
  GeoTiffBlockWriter<std::uint8_t>* slant_out_;
  GeoTiffBlockWriter<std::uint8_t>* ground_out_;
  std::optional<GdalDataset> sp_ds_, mask_ds_;
  std::vector<float> speckled_;
  std::vector<std::uint8_t> mask_, no_data_, ground_no_data_;
};

void picture_blocks(const SlantImagePasses& p, const GreytoneMap& map, const std::string& slant_dir,
                    GeoTiffBlockWriter<std::uint8_t>* slant_out,
                    GeoTiffBlockWriter<std::uint8_t>* ground_out) {
  PicturesPass pass(p, map, slant_dir, slant_out, ground_out);
  run_pass(p.group, p.order, pass);
  pass.release();
}

}  // namespace

std::vector<std::uint64_t> median_ranks(std::uint64_t n, bool both_middles) {
  if (both_middles && n % 2 == 0) return {n / 2 - 1, n / 2};
  return {n / 2};
}

double median_value(const FloatRankSelect& sel, std::uint64_t n, bool both_middles) {
  const double upper = sel.value(both_middles && n % 2 == 0 ? 1 : 0);
  if (!(both_middles && n % 2 == 0)) return upper;
  const double lower = sel.value(0);
  return 0.5 * (lower + upper);
}

std::pair<double, std::string> share_from_rank0(ProcessGroup& group, double value,
                                                const std::string& text) {
  if (group.size() == 1) return {value, text};
  std::array<char, sizeof(double)> v_bytes{};
  std::memcpy(v_bytes.data(), &value, sizeof(double));
  const std::string all = std::string(v_bytes.data(), v_bytes.size()) + text;
  const std::vector<char> mine(all.begin(), all.end());
  const std::vector<char> root = group.all_gather(mine).at(0);
  RIS_CHECK(root.size() >= sizeof(double));
  double v = 0.0;
  std::memcpy(&v, root.data(), sizeof(double));
  return {v, std::string(root.data() + sizeof(double), root.size() - sizeof(double))};
}

int stream_block_lines(int lines, std::int64_t per_line_bytes, int requested,
                       std::int64_t budget_bytes, int ranks) {
  const int n = lines;
  const int block_lines = requested > 0 ? std::min(requested, n)
                                        : static_cast<int>(std::clamp<std::int64_t>(
                                              budget_bytes / per_line_bytes, 16, std::max(n, 16)));
  const int for_ranks =
      ranks > 1 && requested <= 0 ? std::max(16, (n + 4 * ranks - 1) / (4 * ranks)) : n;
  return std::min({block_lines, n, for_ranks});
}

SlarPictures picture_metadata(const GreytoneMap& map, std::uint64_t seed,
                              const std::vector<double>& looks) {
  SlarPictures pic;
  pic.seed = seed;
  pic.looks = looks;
  pic.reference_power_w = map.reference_power_w();
  pic.reference_greytone = map.reference_greytone();
  pic.greytones_per_decade = map.greytones_per_decade();
  pic.film_offset = map.film_offset();
  return pic;
}

void pack_line_block(const StreamLineBlock& k, std::vector<char>& out) {
  const auto put = [&](const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  const int head[5] = {k.l0, k.l1, k.prof.line0, k.prof.lines, k.prof.bins};
  put(head, sizeof(head));
  put(&k.prof.samples_in_swath, sizeof(std::int64_t));
  put(&k.counts, sizeof(SlarLineCounts));
  const std::size_t np = k.prof.power_w.size(), nm = k.scene_mask.size();
  put(&nm, sizeof(nm));
  put(k.prof.power_w.data(), np * sizeof(float));
  put(k.prof.area_m2.data(), np * sizeof(float));
  put(k.prof.touch.data(), np);
  put(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  put(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  put(k.scene_mask.data(), nm);
  put(k.incidence.data(), nm * sizeof(float));
  pack_block_targets(k.targets, out);
  pack_coherent_block(k.coherent, out);
}

StreamLineBlock start_line_block(int b, int block_lines, int lines, int fail_block,
                                 std::vector<StreamLineBlock>& spare) {
  StreamLineBlock k;
  if (!spare.empty()) {  // buffers reused
    k = std::move(spare.back());
    spare.pop_back();
  }
  if (b == fail_block) {
    throw std::runtime_error(fmt::format("block {}: a failure injected by RIS_FAIL_BLOCK", b));
  }
  k.l0 = b * block_lines;
  k.l1 = std::min(lines, k.l0 + block_lines);
  k.counts = SlarLineCounts();
  return k;
}

StreamLineBlock unpack_line_block(const char* p, std::size_t n) {
  const char* const end = p + n;
  const auto get = [&](void* to, std::size_t bytes) {
    RIS_CHECK(std::size_t(end - p) >= bytes);
    std::memcpy(to, p, bytes);
    p += bytes;
  };
  StreamLineBlock k;
  int head[5] = {};
  get(head, sizeof(head));
  k.l0 = head[0];
  k.l1 = head[1];
  k.prof.line0 = head[2];
  k.prof.lines = head[3];
  k.prof.bins = head[4];
  get(&k.prof.samples_in_swath, sizeof(std::int64_t));
  get(&k.counts, sizeof(SlarLineCounts));
  std::size_t nm = 0;
  get(&nm, sizeof(nm));
  const std::size_t np = sz(k.prof.lines) * sz(k.prof.bins);
  k.prof.power_w.resize(np);
  k.prof.area_m2.resize(np);
  k.prof.touch.resize(np);
  k.prof.mapped_count.resize(np);
  k.prof.visible_count.resize(np);
  get(k.prof.power_w.data(), np * sizeof(float));
  get(k.prof.area_m2.data(), np * sizeof(float));
  get(k.prof.touch.data(), np);
  get(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  get(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  k.scene_mask.resize(nm);
  k.incidence.resize(nm);
  get(k.scene_mask.data(), nm);
  get(k.incidence.data(), nm * sizeof(float));
  k.targets = unpack_block_targets(p, end);
  k.coherent = unpack_coherent_block(p, end);
  RIS_CHECK(p == end);
  return k;
}

SlarImage emit_finished_lines(SlarAzimuthIntegrator& az, int n, SlarSimulation& sim,
                              const SwitchedRadarTerms& terms, std::vector<std::uint8_t>& mask) {
  const int bins = sim.image.bins;
  const std::size_t np = sz(n) * sz(bins);
  SlarImage block;
  block.lines = n;
  block.bins = bins;
  block.range = sim.image.range;
  block.mean_power_w.resize(np);
  block.area_m2.resize(np);
  mask.resize(np);
  az.emit(n, block.mean_power_w.data(), block.area_m2.data(), mask.data());
  finish_slar_image(sim, block, terms);
  return block;
}

void count_and_blank_no_data(const SlarImage& block, const std::vector<std::uint8_t>& mask,
                             FloatRankSelect& power, std::vector<float>& mean) {
  mean.assign(block.mean_power_w.begin(), block.mean_power_w.end());
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (valid_power(mean[i], mask[i])) power.count(mean[i]);
    if (mask[i] & pixel_flag::kNoData) mean[i] = std::numeric_limits<float>::quiet_NaN();
  }
}

void StageClock::start(const std::string& name, ProgressBar& bar) {
  seconds_.emplace_back(name, 0.0);
  cpu_mark_ = process_cpu_seconds();
  bar.set_stage(name);
  mark_ = std::chrono::steady_clock::now();
}

void StageClock::done() {
  seconds_.back().second =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - mark_).count();
  cpu_.push_back(process_cpu_seconds() - cpu_mark_);
}

double median_mean_power_pass(const SlantImagePasses& p, FloatRankSelect& power, bool automatic,
                              StageClock& clock) {
  const std::uint64_t n_power = power.total();
  if (!(automatic && n_power > 0)) return std::numeric_limits<double>::quiet_NaN();
  clock.start("median mean power (pass 1b)", *p.bar);
  power.select(median_ranks(n_power, true));
  const int lines = p.sim.image.lines, bins = p.sim.image.bins;
  GdalDataset mean_ds = open_raster(p.dir->path("mean_power_slant.tif").string());
  GdalDataset mask_ds = open_raster(p.dir->path("mask_slant.tif").string());
  std::vector<float> mean;
  std::vector<std::uint8_t> mask;
  for (int k0 = 0; k0 < lines; k0 += p.block_lines) {
    const int n = std::min(p.block_lines, lines - k0);
    const std::size_t np = sz(n) * sz(bins);
    mean.resize(np);
    mask.resize(np);
    read_rows(handle(mean_ds), k0, n, mean.data(), GDT_Float32, "mean_power_slant.tif");
    read_rows(handle(mask_ds), k0, n, mask.data(), GDT_Byte, "mask_slant.tif");
    for (std::size_t i = 0; i < np; ++i)
      if (valid_power(mean[i], mask[i])) power.refine(mean[i]);
  }
  const double median = median_value(power, n_power, true);
  clock.done();
  return median;
}

void pictures_pass(const SlantImagePasses& p, const GreytoneMap& map,
                   const std::string& slant_dir) {
  if (p.group.rank() != 0) {  // blocks computed for rank 0
    picture_blocks(p, map, slant_dir, nullptr, nullptr);
    return;
  }
  const SlarImage& img = p.sim.image;
  const GroundRangeGrid& gg = p.sim.ground_grid;
  const int lines = img.lines;
  const std::string slant_file =
      picture_file("slant_range", img.bins, lines, p.info.max_png_pixels);
  const std::string ground_file =
      picture_file("ground_range", gg.count, lines, p.info.max_png_pixels);
  const auto picture_path = [&](const std::string& file) {
    return file.ends_with(".png") ? p.dir->path("." + file + ".tmp.tif") : p.dir->path(file);
  };
  const auto open_picture = [&](const std::string& file, int cols) {
    const bool png = file.ends_with(".png");
    SlarRasterSpec spec = png ? SlarRasterSpec{} : slar_raster_spec(file, img);
    if (!png) spec.metadata.insert(p.extra_metadata.begin(), p.extra_metadata.end());
    // A GeoTIFF picture with the run's compression (write_slar_products).
    return std::make_unique<GeoTiffBlockWriter<std::uint8_t>>(
        picture_path(file), cols, lines, std::vector<std::string>{spec.band},
        file == "slant_range.tif" ? p.slant_georef : nullptr, spec.nodata, spec.metadata,
        png ? GeoTiffCompression{} : product_tiff_settings(p.info, false));
  };
  {
    auto slant_grey_out = open_picture(slant_file, img.bins);
    auto ground_grey_out = open_picture(ground_file, gg.count);
    picture_blocks(p, map, slant_dir, slant_grey_out.get(), ground_grey_out.get());
    slant_grey_out->close();
    ground_grey_out->close();
  }
  for (const std::string& file : {slant_file, ground_file}) {
    if (!file.ends_with(".png")) continue;
    write_png_gray_from_raster(p.dir->path(file), picture_path(file),
                               png_compression_level(p.info.compression));
    std::filesystem::remove(picture_path(file));
  }
}

}  // namespace ris::detail
