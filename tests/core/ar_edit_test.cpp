// The edits of the scenario's AR section (core/edit/ar_edits.h): each applies and its inverse
// gives the document back exactly; a drag of the placement merges into one edit; bad values are
// refused with a message and change nothing; occluder model paths follow a save to another folder.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "edit/ar_edits.h"

namespace thespis::core::edit {
namespace {

using namespace scenario;

void expectRoundTrip(const Scenario& s, const Result<Edit>& made)
{
    ASSERT_TRUE(made.ok()) << describe(made.error());
    Scenario changed = s;
    ASSERT_TRUE(made->apply(changed).ok());
    EXPECT_NE(changed, s);
    EXPECT_TRUE(made->runtimeScope().empty()) << "the AR section plays no schedule";
    ASSERT_TRUE(made->inverse().apply(changed).ok());
    EXPECT_EQ(changed, s);
}

Scenario withOccluder()
{
    Scenario s;
    s.name = "ar";
    PhantomOccluder table;
    table.name = "table";
    table.shape = PhantomOccluder::Shape::Model;
    table.model = "models/table.glb";
    s.ar.occluders.push_back(table);
    return s;
}

TEST(ArEdits, PlacementAppliesAndTakesBack)
{
    const Scenario s = withOccluder();
    const auto made = setArPlacement(s, {0.05, -0.02}, 30, 0.1);
    expectRoundTrip(s, made);
    Scenario changed = s;
    ASSERT_TRUE(made->apply(changed).ok());
    EXPECT_EQ(changed.ar.offset, (std::array<double, 2>{0.05, -0.02}));
    EXPECT_EQ(changed.ar.heading, 30);
    EXPECT_EQ(changed.ar.scale, 0.1);
    EXPECT_EQ(changed.ar.occluders, s.ar.occluders) << "the occluders stay";
}

TEST(ArEdits, ShadowCatcherAndWholeSpec)
{
    const Scenario s = withOccluder();
    expectRoundTrip(s, setArShadowCatcher(s, false));
    ArSpec spec = s.ar;
    spec.occluders.push_back(PhantomOccluder{});
    spec.scale = 0.2;
    expectRoundTrip(s, setArSpec(s, spec));
}

TEST(ArEdits, ADragOfThePlacementIsOneEdit)
{
    Scenario s = withOccluder();
    const Scenario original = s;
    Edit first = *setArPlacement(s, {0, 0}, 10, 1);
    ASSERT_TRUE(first.apply(s).ok());
    const Edit second = *setArPlacement(s, {0, 0}, 20, 0.5);
    ASSERT_TRUE(first.canMergeWith(second));
    ASSERT_TRUE(second.apply(s).ok());
    first.mergeWith(second);
    EXPECT_EQ(s.ar.heading, 20);
    ASSERT_TRUE(first.inverse().apply(s).ok());
    EXPECT_EQ(s, original);
}

TEST(ArEdits, BadValuesAreRefused)
{
    const Scenario s = withOccluder();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double scale : {0.0, -1.0, nan, 1e6}) {
        const auto made = setArPlacement(s, {0, 0}, 0, scale);
        ASSERT_FALSE(made.ok()) << scale;
        EXPECT_NE(made.error().message.find("scale"), std::string::npos) << made.error().message;
    }
    EXPECT_FALSE(setArPlacement(s, {nan, 0}, 0, 1).ok());
    EXPECT_FALSE(setArPlacement(s, {0, 0}, std::numeric_limits<double>::infinity(), 1).ok());
    ArSpec spec = s.ar;
    spec.occluders.front().model.clear();
    const auto noModel = setArSpec(s, spec);
    ASSERT_FALSE(noModel.ok());
    EXPECT_NE(noModel.error().message.find("\"table\""), std::string::npos) << noModel.error().message;
    spec = s.ar;
    spec.occluders.front().size[1] = 0;
    EXPECT_FALSE(setArSpec(s, spec).ok());
}

TEST(ArEdits, AnEditForAnotherDocumentIsRefused)
{
    Scenario s = withOccluder();
    const Edit made = *setArPlacement(s, {0, 0}, 45, 1);
    s.ar.scale = 3;
    const Scenario before = s;
    EXPECT_FALSE(made.apply(s).ok());
    EXPECT_EQ(s, before);
}

TEST(ArEdits, OccluderModelsFollowASave)
{
    const Scenario s = withOccluder();
    Edit made = *setArPlacement(s, {0, 0}, 0, 0.5);
    made.rebasePaths("/work/a", "/work/a/sub");
    const auto& change = std::get<ArChange>(made.changes().front());
    EXPECT_EQ(change.before.occluders.front().model, "../models/table.glb");
    EXPECT_EQ(change.after.occluders.front().model, "../models/table.glb");
}

} // namespace
} // namespace thespis::core::edit
