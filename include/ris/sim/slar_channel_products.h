// The products of a multi-channel SLAR or SAR run (a radar file with
// [[channel]] tables, docs/radar-format.md; ris/sim/slar_channels.h): each
// channel's products are a one-channel run's (write_slar_products), their
// file names suffixed by the channel's name, as Sentinel-1 names its
// measurement files by polarisation and SNAP its bands (Sigma0_VV):
//
//   mean_power_slant_hh.tif, slant_range_hh.png, geocoded_grey_vv.tif, ...
//
// The products that depend on the geometry alone (the scene-grid maps, the
// slant image's mask and the shadow map: slar_scene_wide_stems) are the same
// for every channel and are written once, without a suffix. metadata.json is
// the first channel's with every file in `products` and a `channels` list:
// each channel's name, frequency, polarisation, backscatter source, radar,
// derived quantities and products.
//
// Example:
//   std::vector<ris::SlarChannelProducts> ch{{"hh", &sim_hh, &pic_hh, ""},
//                                            {"hv", &sim_hv, &pic_hv, ""}};
//   ris::write_slar_channel_products("out", scene, ch, info);
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/scene/scene.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct SlarChannelProducts {
  std::string name;  // the file-name suffix
  const SlarSimulation* sim = nullptr;
  const SlarPictures* pictures = nullptr;
  std::string backscatter_path;  // metadata.json's; "": the run's (info)
};

// The product stems written once for all channels (the geometry's alone).
const std::vector<std::string_view>& slar_scene_wide_stems();

// A channel's file name of a product: "mean_power_slant.tif", "hh" ->
// "mean_power_slant_hh.tif" (the suffix before the first '.').
std::string channel_product_file(const std::string& file, const std::string& channel);

// metadata.json's content (what write_slar_channel_products writes).
nlohmann::json slar_channels_metadata(const Scene& scene,
                                      std::span<const SlarChannelProducts> channels,
                                      const SlarRunInfo& info);

// Writes every channel's selected products (info.products, each stem for
// every channel) into out_dir as one staged folder.
// extra (optional): the run's own further products, written into the
// staging folder it is given; its result's "products" join metadata.json's
// and its other keys are added to it (a quad-pol run's SLCs,
// ris/sim/quad_pol_products.h).
using ExtraRunProducts = std::function<nlohmann::json(const std::filesystem::path& staging)>;
void write_slar_channel_products(const std::filesystem::path& out_dir, const Scene& scene,
                                 std::span<const SlarChannelProducts> channels,
                                 const SlarRunInfo& info, const ExtraRunProducts& extra = {});

}  // namespace ris
