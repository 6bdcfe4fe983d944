// Williams' balanced Latin squares (Williams 1949): carry-over effects of the previous block are
// balanced because every ordered pair of items is adjacent equally often over a full set of rows.
#include <algorithm>
#include <vector>

#include "common/programming_error.h"
#include "study/schedule.h"

namespace monoplane::study {

int balanced_latin_square_rows(int n) {
    MONOPLANE_EXPECTS(n >= 1);
    // For odd n no single n x n square balances the ordered pairs; the square and its mirror do.
    return n % 2 == 0 || n == 1 ? n : 2 * n;
}

std::vector<int> balanced_latin_square_row(int n, int row) {
    MONOPLANE_EXPECTS(n >= 1 && row >= 0 && row < balanced_latin_square_rows(n));
    const int base_row = row % n;
    // First row 0, 1, n-1, 2, n-2, ...: consecutive differences 1, -2, 3, -4, ... are distinct
    // mod n, which is what makes each adjacent pair occur once per n rows (even n).
    std::vector<int> order(static_cast<std::size_t>(n));
    int low = 1;
    int high = n - 1;
    for (int j = 0; j < n; ++j) {
        int first = 0;
        if (j > 0) first = j % 2 == 1 ? low++ : high--;
        order[static_cast<std::size_t>(j)] = (first + base_row) % n;
    }
    if (row >= n) std::reverse(order.begin(), order.end());  // odd n: the mirrored rows
    return order;
}

}  // namespace monoplane::study
