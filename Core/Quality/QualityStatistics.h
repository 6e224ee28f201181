// Statistics of a per-element quality array: count, min, max, mean, standard deviation, the worst element
// and a histogram. NaN values mean "not measured" (skipped cells) and are left out of everything.
//
// Determinism: the array is cut into fixed chunks of kStatisticsChunk values (independent of the number of
// threads); a partial is computed per chunk and the partials are merged in chunk order. A threaded caller
// that computes the chunk partials concurrently and merges them with mergeInOrder() gets bit-identical
// results to computeStatistics(), whatever the thread count.
#pragma once

#include <cstdint>
#include <vector>

namespace volgrid
{
namespace quality
{

constexpr int64_t kStatisticsChunk = 1 << 16;

// Which end of the range is bad, to name the worst element.
enum class Worst
{
  Smallest,
  Largest
};

struct Partial
{
  int64_t count = 0; // non-NaN values
  double min = 0.0, max = 0.0;
  int64_t argMin = -1, argMax = -1; // first index of the min / max
  double mean = 0.0, m2 = 0.0;      // running mean and sum of squared deviations
};

// Partial of values [begin, end) (indices are global, so argMin/argMax are global too).
Partial accumulate(const double* values, int64_t begin, int64_t end);
// Merges partials that cover consecutive index ranges, in that order (Chan et al.'s pairwise update).
Partial mergeInOrder(const std::vector<Partial>& partials);

// numBins + 1 equally spaced edges from min to max; if min == max, the range is widened by
// h = max(0.5, 1e-6 |min|) on both sides so that the bins have positive width. Empty input: [0, 1].
// The values are expected finite (the quality metrics are: see Quality.h).
std::vector<double> binEdges(double min, double max, int numBins);
// Adds the histogram of values [begin, end) into counts (edges.size() - 1 bins). A value v goes to the
// bin i with edges[i] <= v < edges[i+1]; the maximum goes into the last bin; NaN is not counted.
void histogram(const double* values, int64_t begin, int64_t end, const std::vector<double>& edges, int64_t* counts);

struct Statistics
{
  int64_t count = 0;                                     // measured (non-NaN) values
  int64_t skipped = 0;                                   // NaN values
  double min = 0.0, max = 0.0, mean = 0.0, stddev = 0.0; // NaN when count == 0
  int64_t worstIndex = -1;                               // first index of the worst value
  std::vector<double> binEdges;                          // numBins + 1
  std::vector<int64_t> binCounts;                        // numBins, sum == count
};

// Builds the Statistics from the merged partial and the summed histogram counts.
Statistics finish(const Partial& all, int64_t size, Worst worst, std::vector<double> edges,
                  std::vector<int64_t> counts);

// The serial reference: the same chunking, so the same bits as any threaded computation.
Statistics computeStatistics(const double* values, int64_t size, int numBins, Worst worst);

} // namespace quality
} // namespace volgrid
