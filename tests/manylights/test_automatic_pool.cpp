// Where `--pool auto` turns row-column sampling on (engine/manylights/automatic_pool.h): Monte
// Carlo renders of at least five seconds and Metropolis renders of at least fifteen of diffuse
// interiors on lavapipe, where it paid; not under a sky, not with metal or glossy receivers, not
// for short or fixed-count renders, GPUs or the CPU oracle.
#include <gtest/gtest.h>

#include <string>

#include "engine/manylights/automatic_pool.h"
#include "engine/scene/scene_loader.h"

namespace mvpl {
namespace {

using manylights::automatic_pool;
using manylights::diffuse_interior;
using manylights::kAutomaticMinSeconds;
using manylights::kAutomaticMinSecondsMetropolis;
using manylights::kAutomaticPool;

scene::Scene asset(const std::string& path) {
    return scene::load_scene(MVPL_ASSETS_DIR "/" + path);
}

TEST(AutomaticPool, OnForLongRendersOfDiffuseInteriors) {
    const scene::Scene cornell = asset("cornell-box/cbox.gltf");
    EXPECT_TRUE(diffuse_interior(cornell));
    EXPECT_TRUE(diffuse_interior(asset("two-room/two-room.gltf")));
    EXPECT_EQ(automatic_pool(cornell, "mc", kAutomaticMinSeconds, true), kAutomaticPool);
    EXPECT_EQ(automatic_pool(cornell, "mc", 60.0, true), kAutomaticPool);
    EXPECT_EQ(automatic_pool(cornell, "mc", 0.5 * kAutomaticMinSeconds, true), 0u);
    EXPECT_EQ(automatic_pool(cornell, "mc", 0.0, true), 0u);  // a fixed VPL count
    EXPECT_EQ(automatic_pool(cornell, "metropolis", kAutomaticMinSecondsMetropolis, true),
              kAutomaticPool);
    EXPECT_EQ(automatic_pool(cornell, "metropolis", kAutomaticMinSeconds, true), 0u);
    EXPECT_EQ(automatic_pool(cornell, "mc", 60.0, false), 0u);  // a GPU, or the CPU oracle
}

TEST(AutomaticPool, OffUnderASkyAndOnGlossyReceivers) {
    scene::Scene sky = asset("cornell-box/cbox.gltf");
    sky.environment.radiance = Rgb(0.1f);
    EXPECT_FALSE(diffuse_interior(sky));
    EXPECT_EQ(automatic_pool(sky, "mc", 60.0, true), 0u);
    const scene::Scene glossy = asset("glossy/glossy.gltf");  // metal spheres
    EXPECT_FALSE(diffuse_interior(glossy));
    EXPECT_EQ(automatic_pool(glossy, "mc", 60.0, true), 0u);
    scene::Scene metal = asset("cornell-box/cbox.gltf");
    metal.materials[0].metallic = 0.5f;
    EXPECT_FALSE(diffuse_interior(metal));
}

}  // namespace
}  // namespace mvpl
