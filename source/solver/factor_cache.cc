#include <liftoff/base/archives.h>
#include <liftoff/solver/factor_cache.h>

namespace liftoff
{
  FactorCache::FactorCache(const unsigned int capacity)
      : capacity(capacity)
  {}


  void
  FactorCache::keep(Entry &&entry)
  {
    kept.push_back(std::move(entry));
    while (kept.size() > capacity)
      kept.pop_front();
  }


  std::optional<FactorCache::Entry>
  FactorCache::take(const unsigned int key)
  {
    for (auto entry = kept.begin(); entry != kept.end(); ++entry)
      if (entry->key == key)
        {
          std::optional<Entry> found(std::move(*entry));
          kept.erase(entry);
          return found;
        }
    return {};
  }


  void
  FactorCache::clear()
  {
    kept.clear();
  }


  unsigned int
  FactorCache::n_kept() const
  {
    return kept.size();
  }


  void
  FactorCache::save(OutputArchive &archive) const
  {
    const unsigned int n = kept.size();
    archive << n;
    for (const Entry &entry : kept)
      archive << entry.key << entry.factorised_status << entry.velocity_factor
              << entry.factor.is_exact << entry.factor.cg_excess_flops
              << entry.factor.substitution_error;
  }


  void
  FactorCache::load(InputArchive                       &archive,
                    const std::function<void(Entry &)> &factorise)
  {
    kept.clear();
    unsigned int n = 0;
    archive >> n;
    for (unsigned int k = 0; k < n; ++k)
      {
        Entry  entry;
        bool   is_exact = false;
        double excess = 0, error = -1;
        archive >> entry.key >> entry.factorised_status >> entry.velocity_factor
          >> is_exact >> excess >> error;
        factorise(entry);
        entry.factor.is_exact           = is_exact;
        entry.factor.cg_excess_flops    = excess;
        entry.factor.substitution_error = error;
        kept.push_back(std::move(entry));
      }
  }
} // namespace liftoff
