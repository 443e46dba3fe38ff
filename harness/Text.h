// What the benchmark programs share to read their options and write their tables.
#ifndef OSS_HARNESS_TEXT_H
#define OSS_HARNESS_TEXT_H

#include <string>
#include <vector>

namespace osshar {

/** The non-empty items of a comma-separated list ("a,b,,c" gives a, b, c). */
std::vector<std::string> splitList(const std::string& s);

/** v with `decimals` digits after the point ("%.*f"). */
std::string fixed(double v, int decimals);

/** The median of v (the mean of the middle two for an even count), or -1 when v is empty. */
double median(std::vector<double> v);

} // namespace osshar

#endif
