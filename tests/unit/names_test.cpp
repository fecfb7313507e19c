// The name tables of core/names.h: every value has one name and reads back from it, so the
// tools' option checks (which list the names) and the parsers (which read them) agree.
#include <gtest/gtest.h>

#include <set>

#include "accel/settings.h"
#include "core/names.h"
#include "inspect/heatmap.h"
#include "inspect/ray_statistics.h"
#include "inspect/tree_cut.h"
#include "inspect/tree_dump.h"
#include "io/import.h"

using namespace rt;

namespace {

template <class E, std::size_t N>
void expectRoundTrip(const NamedValues<E, N>& table) {
    std::set<std::string> names;
    for (const Named<E>& entry : table) {
        EXPECT_TRUE(names.insert(entry.name).second) << "the name " << entry.name << " is given twice";
        EXPECT_EQ(parseNamed(table, entry.name), entry.value) << entry.name;
        EXPECT_STREQ(nameOf(table, entry.value), entry.name);
    }
    EXPECT_EQ(parseNamed(table, "no such name"), std::nullopt);
}

}  // namespace

TEST(Names, EveryTableReadsBackWhatItWrites) {
    expectRoundTrip(kAccelKindNames);
    expectRoundTrip(kKdSplitMethodNames);
    expectRoundTrip(kHeatScaleNames);
    expectRoundTrip(kPixelRaysNames);
    expectRoundTrip(kUpAxisNames);
    expectRoundTrip(kLeafChoiceNames);
    expectRoundTrip(kTreeDumpFormatNames);
    expectRoundTrip(kOnOffNames);
}

TEST(Names, ListedInTheTablesOrder) {
    EXPECT_EQ(namesOf(kAccelKindNames), (std::vector<std::string>{"naive", "bsp", "kd", "bvh"}));
    EXPECT_STREQ(accelKindName(AccelKind::Bsp), "bsp");
    EXPECT_EQ(parseKdSplitMethod("sample"), KdSplitMethod::Sample);
}
