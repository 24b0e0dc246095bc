// Table: measured sigma0 against incidence, read from a CSV file.
//
//   sigma0_dB(theta) = linear interpolation in dB between the listed angles
//
// Source: the seed's method (empirical data from the Remote Sensing
// Laboratory's data bank stored at 1 deg steps from 0 to 90 deg, seed report
// p. 13) and MODEL.md section 4. File format: include/ris/backscatter/
// sigma0_table.h and docs/backscatter.md.
// Parameters:
//   file      the CSV file, relative to the library's folder
//   category  the table's category id (default: the library category's id)
//   clamp     optional bool; overrides the file's "# clamp:" directive
// Validity: only the bands (frequency and polarisation) and angles the table
// lists; any other band is an InputError naming the bands it has, an angle
// outside the listed range is an InputError unless clamp is set.
//
// TOML:  [category.model]
//        name = "table"
//        file = "ku-geometric-8.6GHz.csv"
#include <algorithm>
#include <filesystem>

#include "backscatter/models/models.h"
#include "ris/backscatter/sigma0_table.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris::detail {
namespace {

class TableModel final : public BackscatterModel {
 public:
  TableModel(std::shared_ptr<const Sigma0Table> table, std::uint16_t category, bool clamp,
             std::string file, std::string key)
      : table_(std::move(table)),
        category_(category),
        clamp_(clamp),
        file_(std::move(file)),
        key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    if (table_->find(category_, band) == nullptr) {
      throw InputError(file_, key_,
                       fmt::format("table {} has no rows for category {} at {:g} GHz {} (it "
                                   "has: {}); add a per-band entry with another model for this "
                                   "band",
                                   table_->path(), category_, band.frequency_hz / 1e9,
                                   to_string(band.polarisation), table_->bands_of(category_)));
    }
  }
  double sigma0(double incidence_rad, const RadarBand& band) const override {
    const Sigma0Table::Curve* c = table_->find(category_, band);
    if (c == nullptr) check_band(band);  // throws
    return db_to_linear(table_->eval_db(*c, incidence_rad, clamp_));
  }
  std::string describe() const override {
    return fmt::format("table {} category {}{}", table_->path(), category_,
                       clamp_ ? " (clamped)" : "");
  }

 private:
  std::shared_ptr<const Sigma0Table> table_;
  std::uint16_t category_;
  bool clamp_;
  std::string file_;
  std::string key_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_table_model(ConfigTable& params, const ModelContext& ctx) {
  const std::string file = params.get_string("file");
  std::filesystem::path path(file);
  if (path.is_relative() && !ctx.base_dir.empty())
    path = std::filesystem::path(ctx.base_dir) / path;
  const std::string resolved = path.lexically_normal().string();
  std::shared_ptr<const Sigma0Table> table;
  if (ctx.table_cache != nullptr) {
    auto it = ctx.table_cache->find(resolved);
    if (it != ctx.table_cache->end()) table = it->second;
  }
  if (!table) {
    if (!path_exists(path)) {
      params.fail("file",
                  fmt::format("table file \"{}\" not found (resolved to {})", file, resolved));
    }
    table = std::make_shared<const Sigma0Table>(Sigma0Table::load(resolved));
    if (ctx.table_cache != nullptr) (*ctx.table_cache)[resolved] = table;
  }
  std::int64_t category = ctx.category_id;
  if (params.has("category") || category < 0) category = params.get_int("category");
  const auto ids = table->categories();
  if (category < 1 || category > 65535 ||
      std::find(ids.begin(), ids.end(), static_cast<std::uint16_t>(category)) == ids.end()) {
    params.fail(params.has("category") ? "category" : "file",
                fmt::format("table {} has no rows for category {}", resolved, category));
  }
  const bool clamp = params.get_bool_or("clamp", table->clamp());
  params.finish();
  return std::make_unique<TableModel>(table, static_cast<std::uint16_t>(category), clamp, ctx.file,
                                      params.key_path("file"));
}

}  // namespace ris::detail
