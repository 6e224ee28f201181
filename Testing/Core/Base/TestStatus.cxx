#include "Status.h"

#include <gtest/gtest.h>

TEST(Status, FailureCarriesKindMessageAndIds)
{
  volgrid::Status s = volgrid::Status::failure(volgrid::ErrorKind::OpenSurface, "3 open edges", { 7, 9 });
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.kind, volgrid::ErrorKind::OpenSurface);
  EXPECT_STREQ(volgrid::errorKindName(s.kind), "open surface");
  ASSERT_EQ(s.firstIds.size(), 2u);
  EXPECT_TRUE(volgrid::Status::success().ok());
}
