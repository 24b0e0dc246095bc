// Where sigma0 comes from: the interface between the backscatter models and
// the simulation.
//
// A Sigma0Source answers "sigma0 of category c at local incidence theta for
// this band". It is consulted only while building a Sigma0Lut, once per run
// (DESIGN.md principle 5: decide outside the loop); the hot loops read the
// table, never a virtual function.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/backscatter/polarisation.h"

namespace ris {

class Sigma0Source {
 public:
  virtual ~Sigma0Source() = default;

  // Whether the source can give sigma0 for this category.
  virtual bool has_category(std::uint16_t category) const = 0;

  // sigma0 (linear, per unit true surface area, >= 0) at local incidence
  // incidence_rad in [0, pi/2]. Called only for categories with
  // has_category() true. May throw InputError (e.g. a band outside a model's
  // validity range).
  virtual double sigma0(std::uint16_t category, double incidence_rad,
                        const RadarBand& band) const = 0;

  // A human-readable name for the category ("tall corn"), or its number.
  virtual std::string category_name(std::uint16_t category) const = 0;

  // Where the values come from, for metadata ("table data/backscatter/x.csv").
  virtual std::string description() const = 0;

  // Added for the category libraries (backward compatible: defaults below).
  // Every category the source defines, ascending; empty when the source
  // cannot list them.
  virtual std::vector<std::uint16_t> category_ids() const { return {}; }
  // Display colour (R, G, B) of a category for legends and category maps, or
  // nullopt when the source gives none.
  virtual std::optional<std::array<std::uint8_t, 3>> category_colour(std::uint16_t) const {
    return std::nullopt;
  }
  // The model or table behind a category at a band, one line ("water_cloud
  // A = ... over oh1992 ..."), for metadata. Default: description().
  virtual std::string category_model(std::uint16_t, const RadarBand&) const {
    return description();
  }

  // Added for the LUT build (backward compatible: the default calls sigma0()
  // per angle). sigma0 of one category at many angles, out[i] at
  // incidence_rad[i]; a source may look the category's model up once for the
  // whole curve instead of once per angle. Same values as sigma0().
  virtual void sigma0_curve(std::uint16_t category, const double* incidence_rad, std::size_t n,
                            const RadarBand& band, double* out) const {
    for (std::size_t i = 0; i < n; ++i) out[i] = sigma0(category, incidence_rad[i], band);
  }
};

}  // namespace ris
