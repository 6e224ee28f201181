#include "QualityStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace volgrid
{
namespace quality
{

Partial accumulate(const double* values, int64_t begin, int64_t end)
{
  Partial p;
  // Two passes over the chunk (it is in cache): the mean, then the squared deviations about it.
  double sum = 0.0;
  for (int64_t i = begin; i < end; ++i)
  {
    const double v = values[i];
    if (std::isnan(v))
      continue;
    if (p.count == 0 || v < p.min)
    {
      p.min = v;
      p.argMin = i;
    }
    if (p.count == 0 || v > p.max)
    {
      p.max = v;
      p.argMax = i;
    }
    sum += v;
    ++p.count;
  }
  if (p.count == 0)
    return p;
  p.mean = sum / static_cast<double>(p.count);
  double m2 = 0.0;
  for (int64_t i = begin; i < end; ++i)
  {
    const double v = values[i];
    if (!std::isnan(v))
      m2 += (v - p.mean) * (v - p.mean);
  }
  p.m2 = m2;
  return p;
}

Partial mergeInOrder(const std::vector<Partial>& partials)
{
  Partial r;
  for (const Partial& p : partials)
  {
    if (p.count == 0)
      continue;
    if (r.count == 0)
    {
      r = p;
      continue;
    }
    // Strict comparisons keep the first index on ties, since partials come in index order.
    if (p.min < r.min)
    {
      r.min = p.min;
      r.argMin = p.argMin;
    }
    if (p.max > r.max)
    {
      r.max = p.max;
      r.argMax = p.argMax;
    }
    const double n1 = static_cast<double>(r.count), n2 = static_cast<double>(p.count);
    const double n = n1 + n2;
    const double delta = p.mean - r.mean;
    r.mean += delta * (n2 / n);
    r.m2 += p.m2 + delta * delta * (n1 * n2 / n);
    r.count += p.count;
  }
  return r;
}

std::vector<double> binEdges(double min, double max, int numBins)
{
  numBins = std::max(numBins, 1);
  if (!(min <= max)) // empty input
  {
    min = 0.0;
    max = 1.0;
  }
  else if (min == max)
  {
    const double h = std::max(0.5, 1e-6 * std::fabs(min));
    min -= h;
    max += h;
  }
  std::vector<double> edges(static_cast<size_t>(numBins) + 1);
  const double width = (max - min) / numBins;
  for (int i = 0; i <= numBins; ++i)
  {
    edges[i] = min + width * i;
  }
  edges[numBins] = max;
  return edges;
}

void histogram(const double* values, int64_t begin, int64_t end, const std::vector<double>& edges, int64_t* counts)
{
  const int numBins = static_cast<int>(edges.size()) - 1;
  const double lo = edges.front(), hi = edges.back();
  const double scale = numBins / (hi - lo);
  for (int64_t i = begin; i < end; ++i)
  {
    const double v = values[i];
    if (std::isnan(v))
      continue;
    // Estimate the bin, then correct it against the stored edges so that the rule in the header holds
    // exactly despite rounding in the estimate.
    int b = static_cast<int>(std::min(std::max((v - lo) * scale, 0.0), static_cast<double>(numBins - 1)));
    while (b > 0 && v < edges[b])
      --b;
    while (b < numBins - 1 && v >= edges[b + 1])
      ++b;
    ++counts[b];
  }
}

Statistics finish(const Partial& all, int64_t size, Worst worst, std::vector<double> edges, std::vector<int64_t> counts)
{
  Statistics s;
  s.count = all.count;
  s.skipped = size - all.count;
  if (all.count == 0)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.min = s.max = s.mean = s.stddev = nan;
  }
  else
  {
    s.min = all.min;
    s.max = all.max;
    s.mean = all.mean;
    s.stddev = std::sqrt(all.m2 / static_cast<double>(all.count)); // population standard deviation
    s.worstIndex = worst == Worst::Smallest ? all.argMin : all.argMax;
  }
  s.binEdges = std::move(edges);
  s.binCounts = std::move(counts);
  return s;
}

Statistics computeStatistics(const double* values, int64_t size, int numBins, Worst worst)
{
  std::vector<Partial> partials;
  for (int64_t b = 0; b < size; b += kStatisticsChunk)
  {
    partials.push_back(accumulate(values, b, std::min(size, b + kStatisticsChunk)));
  }
  const Partial all = mergeInOrder(partials);
  std::vector<double> edges = all.count ? binEdges(all.min, all.max, numBins) : binEdges(1.0, 0.0, numBins);
  std::vector<int64_t> counts(edges.size() - 1, 0);
  histogram(values, 0, size, edges, counts.data());
  return finish(all, size, worst, std::move(edges), std::move(counts));
}

} // namespace quality
} // namespace volgrid
