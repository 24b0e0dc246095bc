// Sensitivity analysis (ris/analysis/sensitivity.h): the detail reductions do what
// they say, no reduction gives no difference, coarser ground truth moves the
// image monotonically, one row per grid point, bad keys and values refused.
#include "ris/analysis/sensitivity.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <memory>

#include "ris/backscatter/library.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"

namespace ris {
namespace {

TEST(Sensitivity, DetailReductionsAverageRoundAndMislabelAsDocumented) {
  Scene s = Scene::flat(4, 4, 10.0, 0.0f, 1);
  for (int i = 0; i < 16; ++i) s.elevation_m[static_cast<std::size_t>(i)] = float(i);
  s.category[s.index(0, 0)] = 2;
  s.category[s.index(0, 1)] = 2;
  s.category[s.index(1, 0)] = 2;
  const Scene c = coarsened_scene(s, 2);
  // The north-west block: elevations 0, 1, 4, 5 (mean 2.5), three of category 2.
  for (int r : {0, 1})
    for (int col : {0, 1}) {
      EXPECT_FLOAT_EQ(c.elevation_m[c.index(r, col)], 2.5f);
      EXPECT_EQ(c.category[c.index(r, col)], 2);
    }
  EXPECT_FLOAT_EQ(c.elevation_m[c.index(3, 3)], (10 + 11 + 14 + 15) / 4.0f);
  EXPECT_EQ(c.category[c.index(3, 3)], 1);
  const Scene q = quantised_scene(s, 4.0);
  EXPECT_FLOAT_EQ(q.elevation_m[5], 4.0f);
  EXPECT_FLOAT_EQ(q.elevation_m[7], 8.0f);

  // Mislabelling: none at 0, about the fraction asked, a superset as it grows.
  Scene big = Scene::flat(100, 100, 10.0, 0.0f, 1);
  for (std::size_t i = 0; i < big.size(); i += 2) big.category[i] = 3;
  const Scene none = mislabelled_scene(big, 0.0, 7);
  EXPECT_EQ(none.category, big.category);
  const Scene m10 = mislabelled_scene(big, 0.10, 7), m30 = mislabelled_scene(big, 0.30, 7);
  int changed10 = 0, changed30 = 0, lost = 0;
  for (std::size_t i = 0; i < big.size(); ++i) {
    changed10 += m10.category[i] != big.category[i];
    changed30 += m30.category[i] != big.category[i];
    lost += m10.category[i] != big.category[i] && m30.category[i] == big.category[i];
  }
  EXPECT_NEAR(changed10 / 10000.0, 0.10, 0.01);  // binomial sd 0.003
  EXPECT_NEAR(changed30 / 10000.0, 0.30, 0.015);
  EXPECT_EQ(lost, 0);
}

SensitivityStudy standard_study() {
  SensitivityStudy st;
  st.scene = std::make_shared<Scene>(
      load_scene_source(std::string(ris::test::data_dir()) + "/scenes/ku-geometric.toml").scene);
  st.radar = load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  st.backscatter_path = default_sigma0_library_path();
  st.sigma0 = load_sigma0_source(st.backscatter_path);
  return st;
}

TEST(Sensitivity, StandardSceneNoReductionIsZeroAndCoarserIsMonotonic) {
  const SensitivityStudy st = standard_study();
  int streamed = 0;
  const std::vector<SensitivityRow> rows =
      run_sensitivity(st, {{"mislabel", {0.0, 0.2}}, {"cell_factor", {1, 2, 4, 8}}},
                      [&](const SensitivityRow&) { ++streamed; });
  ASSERT_EQ(rows.size(), 6u);  // one row per grid point
  EXPECT_EQ(streamed, 6);
  EXPECT_EQ(rows[0].rms_db, 0.0);  // mislabel 0: the reference itself
  EXPECT_EQ(rows[0].pearson, 1.0);
  EXPECT_GT(rows[1].rms_db, 0.1);
  EXPECT_EQ(rows[2].rms_db, 0.0);  // cell factor 1: the reference itself
  for (std::size_t i = 3; i < 6; ++i) {
    EXPECT_GT(rows[i].rms_db, rows[i - 1].rms_db) << "cell factor " << rows[i].value;
    EXPECT_LT(rows[i].pearson, rows[i - 1].pearson) << "cell factor " << rows[i].value;
  }
}

TEST(Sensitivity, BadKeysAndValuesAreRefused) {
  const SensitivityStudy st = standard_study();
  EXPECT_THROW(run_sensitivity(st, {{"altitude", {1.0}}}), InputError);
  EXPECT_THROW(run_sensitivity(st, {{"cell_factor", {1.5}}}), InputError);
  EXPECT_THROW(run_sensitivity(st, {{"mislabel", {1.5}}}), InputError);
  EXPECT_THROW(run_sensitivity(st, {{"frequency", {-1.0}}}), InputError);
}

}  // namespace
}  // namespace ris
