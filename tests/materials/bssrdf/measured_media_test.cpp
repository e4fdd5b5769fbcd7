#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "materials/bssrdf/measured_media.h"

namespace scatterlab {
namespace measured_media_test {

nlohmann::json mediaFile() {
  std::ifstream file(std::filesystem::path(SCATTERLAB_DATA_DIR) / "media.json");
  return nlohmann::json::parse(file);
}

TEST(MeasuredMedia, CompiledTableIsTheDataFile) {
  const nlohmann::json file = mediaFile();
  EXPECT_NE(file.at("source").get<std::string>().find("Jensen"), std::string::npos);
  EXPECT_EQ(file.at("g"), 0);
  const auto& media = file.at("media");
  ASSERT_EQ(media.size(), measuredMedia().size());
  ASSERT_EQ(media.size(), 12u);
  for (const auto& entry : media) {
    const std::string name = entry.at("name");
    SCOPED_TRACE(name);
    const MeasuredMedium* m = findMeasuredMedium(name);
    ASSERT_NE(m, nullptr);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(m->sigmaSPrime[c], entry.at("sigma_s_prime")[size_t(c)].get<double>());
      EXPECT_EQ(m->sigmaA[c], entry.at("sigma_a")[size_t(c)].get<double>());
    }
    EXPECT_EQ(m->eta, entry.at("eta").get<double>());
  }
}

TEST(MeasuredMedia, TwelveDistinctNamesAndMarbleAtOnePointFive) {
  const auto names = measuredMediumNames();
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 12u);
  EXPECT_EQ(findMeasuredMedium("Marble")->eta, 1.5);
  EXPECT_EQ(findMeasuredMedium("Skin1")->eta, 1.3);
  EXPECT_EQ(findMeasuredMedium("skin1"), nullptr);  // names are case-sensitive, as in pbrt
}

}  // namespace measured_media_test
}  // namespace scatterlab
