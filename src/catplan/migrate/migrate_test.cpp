#include "catplan/migrate/migration.hpp"

#include <gtest/gtest.h>

TEST(Migrate, Builds) {
    SUCCEED();
}
