// LastKey (shadelab/last_key.h): what the kept labels and texts are remade by, so a frame that shows the
// same values makes nothing and one that shows others never shows a stale value.
#include "shadelab/last_key.h"

#include <string>

#include <gtest/gtest.h>

namespace shadelab {
namespace {

TEST(LastKey, ChangedOnlyWhenTheKeyDiffersFromTheLastOne) {
    LastKey<std::string> last;
    EXPECT_TRUE(last.changed("level 2")) << "the first key: nothing was made yet";
    EXPECT_FALSE(last.changed("level 2"));
    EXPECT_TRUE(last.changed("level 3"));
    EXPECT_TRUE(last.changed("level 2")) << "only the last key is kept";
    EXPECT_FALSE(last.changed("level 2"));
}

TEST(LastKey, ForgetMakesTheSameKeyChangeAgain) {
    LastKey<int> last;
    ASSERT_TRUE(last.changed(7));
    last.forget(); // the value for 7 could not be made
    EXPECT_TRUE(last.changed(7));
    EXPECT_FALSE(last.changed(7));
}

} // namespace
} // namespace shadelab
