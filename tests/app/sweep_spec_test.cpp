// A sweep spec's expansion (app/sweep/sweep_spec.h): the order of the variants, the operators'
// values and the seeds, without running anything.
#include "app/sweep/sweep_spec.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_code.h"

namespace scatterlab {
namespace sweep_spec_test {

using nlohmann::json;

TEST(SweepSpec, VariantsFollowSortedKeysWithTheLastFastest) {
  const json material = {{"type", "conductor"},
                         {"alpha", {{"$values", {0.1, 0.2}}}},
                         {"distribution", {{"$values", {"ggx", "beckmann"}}}}};
  const std::vector<json> variants = expandSweepValue(material, "m");
  ASSERT_EQ(variants.size(), 4u);
  EXPECT_EQ(variants[0], (json{{"type", "conductor"}, {"alpha", 0.1}, {"distribution", "ggx"}}));
  EXPECT_EQ(variants[1], (json{{"type", "conductor"}, {"alpha", 0.1}, {"distribution", "beckmann"}}));
  EXPECT_EQ(variants[3], (json{{"type", "conductor"}, {"alpha", 0.2}, {"distribution", "beckmann"}}));
}

TEST(SweepSpec, OperatorsInsideArraysAndNestedObjectsExpand) {
  const json material = {{"type", "blend"},
                         {"weight", 0.5},
                         {"materials",
                          {{{"type", "lambertian"}, {"albedo", {0.1, {{"$values", {0.2, 0.3}}}, 0.4}}},
                           {{"type", "conductor"}}}}};
  const std::vector<json> variants = expandSweepValue(material, "m");
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[1]["materials"][0]["albedo"], json({0.1, 0.3, 0.4}));
}

TEST(SweepSpec, LinspaceAndLogspaceEndExactlyOnTheirEndPoints) {
  const std::vector<json> linear = expandSweepValue({{"$linspace", {0.1, 0.7, 4}}}, "x");
  ASSERT_EQ(linear.size(), 4u);
  EXPECT_EQ(linear.front().get<double>(), 0.1);
  EXPECT_EQ(linear.back().get<double>(), 0.7);
  EXPECT_NEAR(linear[1].get<double>(), 0.3, 1e-15);  // one rounding of 0.1 + 0.6 / 3
  const std::vector<json> log = expandSweepValue({{"$logspace", {0.01, 1, 3}}}, "x");
  EXPECT_EQ(log.front().get<double>(), 0.01);
  EXPECT_NEAR(log[1].get<double>(), 0.1, 1e-15);  // 0.01 * 100^(1/2), a few roundings
  EXPECT_EQ(log.back().get<double>(), 1.0);
}

TEST(SweepSpec, OperatorsWithBadArgumentsAreRefused) {
  EXPECT_THROW(expandSweepValue({{"$linspace", {0, 1}}}, "x"), InputError);
  EXPECT_THROW(expandSweepValue({{"$linspace", {0, 1, 1}}}, "x"), InputError);
  EXPECT_THROW(expandSweepValue({{"$logspace", {0, 1, 3}}}, "x"), InputError);
  EXPECT_THROW(expandSweepValue({{"$values", json::array()}}, "x"), InputError);
  EXPECT_THROW(expandSweepValue({{"$grid", {1, 2}}}, "x"), InputError);
}

TEST(SweepSpec, AnExplodingProductIsRefused) {
  const json axis = {{"$linspace", {0, 1, 1000}}};
  EXPECT_THROW(expandSweepValue(json::array({axis, axis, axis}), "x"), InputError);
}

TEST(SweepSpec, TasksAreMaterialsTimesVaryWithSeedsFromSpecAndIndex) {
  const json spec = {{"command", "fit"},
                     {"materials", {{{"type", "lambertian"}}, {{"type", "phong"}}}},
                     {"options", {{"samples", 1000}}},
                     {"vary", {{"metric", {"l2", "ngan"}}, {"model", {"lambertian", "phong"}}}}};
  const SweepSpec sweep = expandSweepSpec(spec, ".", "test");
  ASSERT_EQ(sweep.tasks.size(), 8u);
  EXPECT_EQ(sweep.tasks[1].vary, (json{{"metric", "l2"}, {"model", "phong"}}));
  EXPECT_EQ(sweep.tasks[4].material, (json{{"type", "phong"}}));
  EXPECT_EQ(sweep.tasks[5].arguments,
            (std::vector<std::string>{"fit", "{\"type\":\"phong\"}", "--samples", "1000", "--metric", "l2",
                                      "--model", "phong", "--seed", std::to_string(sweep.tasks[5].seed),
                                      "--json"}));
  // The same spec gives the same hash and seeds; a changed option changes both.
  EXPECT_EQ(expandSweepSpec(spec, ".", "again").tasks[7].seed, sweep.tasks[7].seed);
  json changed = spec;
  changed["options"]["samples"] = 2000;
  const SweepSpec other = expandSweepSpec(changed, ".", "test");
  EXPECT_NE(other.hash, sweep.hash);
  EXPECT_NE(other.tasks[0].seed, sweep.tasks[0].seed);
}

TEST(SweepSpec, ShardsAreRoundRobinAndValidated) {
  const SweepShard shard = parseSweepShard("2/3");
  EXPECT_TRUE(shard.contains(1));
  EXPECT_TRUE(shard.contains(4));
  EXPECT_FALSE(shard.contains(2));
  EXPECT_THROW(parseSweepShard("0/3"), InputError);
  EXPECT_THROW(parseSweepShard("4/3"), InputError);
  EXPECT_THROW(parseSweepShard("1/0"), InputError);
  EXPECT_THROW(parseSweepShard("-1/3"), InputError);
}

}  // namespace sweep_spec_test
}  // namespace scatterlab
