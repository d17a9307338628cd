#pragma once

/**
 * The archive types alone, for headers that only declare save() and load():
 * boost's archive headers are needed only where an archive is read or
 * written (base/archives.h).
 */
namespace boost
{
  namespace archive
  {
    class binary_oarchive;
    class binary_iarchive;
  } // namespace archive
} // namespace boost

namespace liftoff
{
  /// What each part of the state writes itself to and reads itself from.
  using OutputArchive = boost::archive::binary_oarchive;
  using InputArchive  = boost::archive::binary_iarchive;
} // namespace liftoff
