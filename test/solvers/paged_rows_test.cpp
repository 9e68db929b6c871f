// PagedRows: LA-LaCAM's node rows keep their contents and their addresses as the search grows.
#include "fleet_planner/solvers/lacam/paged_rows.h"

#include <gtest/gtest.h>

#include <vector>

namespace fleet_planner {
namespace {

TEST(PagedRows, RowsKeepTheirContentsAndAddressesAcrossManyPages) {
  const int width = 37;  // not a power of two: rows straddle no page, pages end short
  PagedRows<int> rows(width);
  std::vector<const int*> addresses;
  const int count = 20000;  // 256 rows of 148 bytes a page: 79 pages
  for (int r = 0; r < count; ++r) {
    int* row = rows.append();
    for (int i = 0; i < width; ++i) row[i] = r * 1000 + i;
    addresses.push_back(row);
  }
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(count));
  for (int r = 0; r < count; ++r) {
    ASSERT_EQ(rows.row(r), addresses[r]) << "row " << r << " moved";
    for (int i = 0; i < width; ++i) ASSERT_EQ(rows.row(r)[i], r * 1000 + i) << "row " << r << " entry " << i;
  }
}

TEST(PagedRows, BytesGrowByWholePagesOnlyWhenAPageIsFull) {
  PagedRows<float> rows(100);  // 400 bytes a row: 128 rows in a 64 KB page
  EXPECT_EQ(rows.bytes(), 0.0);
  rows.append();
  const double page = rows.bytes();
  EXPECT_GE(page, 100 * sizeof(float));
  EXPECT_LE(page, 65536.0);
  const std::size_t per_page = static_cast<std::size_t>(page / (100 * sizeof(float)));
  while (rows.size() < per_page) rows.append();
  EXPECT_EQ(rows.bytes(), page);
  rows.append();
  EXPECT_EQ(rows.bytes(), 2 * page);
}

TEST(PagedRows, ARowWiderThanAPageGetsAPageOfItsOwn) {
  PagedRows<double> rows(20000);  // 160 KB a row
  double* first = rows.append();
  double* second = rows.append();
  first[19999] = 1.0;
  second[0] = 2.0;
  EXPECT_EQ(rows.row(0)[19999], 1.0);
  EXPECT_EQ(rows.row(1)[0], 2.0);
  EXPECT_EQ(rows.bytes(), 2 * 20000 * sizeof(double));
}

}  // namespace
}  // namespace fleet_planner
