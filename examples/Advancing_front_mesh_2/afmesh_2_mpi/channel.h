// afmesh_2_mpi: MPI as the tool uses it: the run's communicator, and
// vectors of plain values sent between two ranks (in chunks, as MPI counts
// are ints).
#ifndef AFMESH_2_MPI_CHANNEL_H
#define AFMESH_2_MPI_CHANNEL_H

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace afmesh_2_mpi {

// MPI started for the process's life; finalised on the way out.
struct Mpi_session
{
  int rank = 0, ranks = 1;
  Mpi_session(int& argc, char**& argv)
  {
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  }
  ~Mpi_session() { MPI_Finalize(); }
  Mpi_session(const Mpi_session&) = delete;
  Mpi_session& operator=(const Mpi_session&) = delete;
};

// A 64-bit FNV-1a digest of `n` bytes, continuing from `h`: what the ranks
// compare (their decompositions, the options of a resumed run) and the
// checksum of a kept part.
constexpr std::uint64_t digest_start = 1469598103934665603ull;
inline std::uint64_t digest_bytes(const void* data, std::size_t n, std::uint64_t h = digest_start)
{
  const unsigned char* b = static_cast<const unsigned char*>(data);
  for(std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

// The message tags of the tool's exchanges.
enum Tag : int {
  BAND = 1,
  BAND_VERDICT,
  BAND_IDS,
  MERGED_POINTS,
  MERGED_TRIANGLES,
  OUTPUT_NAME,
  FIT,
  MERGED_SEGMENTS,
  MERGED_MARKERS,
  MERGED_REGIONS,
  MERGED_SEGMENT_MARKERS,
  QUALITY_RATIOS,
  QUALITY_EDGES,
  MIN_ANGLE_EDGES,
  MIN_ANGLE_SPLITS,
  MIN_ANGLE_OPPOSITE,
  MIN_ANGLE_IDS
};

// Values are sent as bytes in chunks of at most 1 GiB.
constexpr std::size_t chunk_bytes = std::size_t(1) << 30;

// Sends the `count` values at `values`, as receive_vector() takes them.
template <class T>
void send_values(const T* values, std::size_t count, int to, Tag tag)
{
  static_assert(std::is_trivially_copyable<T>::value, "plain values only");
  const std::uint64_t n = count;
  MPI_Send(&n, 1, MPI_UINT64_T, to, tag, MPI_COMM_WORLD);
  const char* bytes = reinterpret_cast<const char*>(values);
  const std::size_t total = count * sizeof(T);
  for(std::size_t done = 0; done < total;) {
    const std::size_t k = (std::min)(chunk_bytes, total - done);
    MPI_Send(bytes + done, int(k), MPI_BYTE, to, tag, MPI_COMM_WORLD);
    done += k;
  }
}

template <class T>
void send_vector(const std::vector<T>& v, int to, Tag tag)
{
  send_values(v.data(), v.size(), to, tag);
}

// Values sent in chunks of any size, ended by an empty one: a sender
// calls send_chunk() for each (empty ones are skipped), then
// end_chunks(); the receiver gets each with receive_chunks().
template <class T>
void send_chunk(const T* values, std::size_t n, int to, Tag tag)
{
  if(n > 0) send_values(values, n, to, tag);
}

template <class T>
void end_chunks(int to, Tag tag)
{
  send_values<T>(nullptr, 0, to, tag);
}

template <class T>
std::vector<T> receive_vector(int from, Tag tag);

// Hands each chunk from `from` to `take(values, n)` until the empty one.
template <class T, class Take>
void receive_chunks(int from, Tag tag, const Take& take)
{
  for(;;) {
    const std::vector<T> chunk = receive_vector<T>(from, tag);
    if(chunk.empty()) return;
    take(chunk.data(), chunk.size());
  }
}

template <class T>
std::vector<T> receive_vector(int from, Tag tag)
{
  static_assert(std::is_trivially_copyable<T>::value, "plain values only");
  std::uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::vector<T> v(n);
  char* bytes = reinterpret_cast<char*>(v.data());
  const std::size_t total = v.size() * sizeof(T);
  for(std::size_t done = 0; done < total;) {
    const std::size_t k = (std::min)(chunk_bytes, total - done);
    MPI_Recv(bytes + done, int(k), MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    done += k;
  }
  return v;
}

inline bool all_ranks(bool mine)
{
  int in = mine ? 1 : 0, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return out != 0;
}

inline bool any_rank(bool mine) { return !all_ranks(!mine); }

inline std::uint64_t sum_over_ranks(std::uint64_t mine)
{
  std::uint64_t out = 0;
  MPI_Allreduce(&mine, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  return out;
}

// The sum of `mine` over the ranks below this one.
inline std::uint64_t exclusive_scan(std::uint64_t mine, int rank)
{
  std::uint64_t out = 0;
  MPI_Exscan(&mine, &out, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  return rank == 0 ? 0 : out; // MPI leaves rank 0's result undefined
}

template <class T>
std::vector<T> gather_to_root(T mine, int ranks)
{
  static_assert(std::is_trivially_copyable<T>::value, "plain values only");
  std::vector<T> all(static_cast<std::size_t>(ranks));
  MPI_Gather(&mine, int(sizeof(T)), MPI_BYTE, all.data(), int(sizeof(T)), MPI_BYTE, 0, MPI_COMM_WORLD);
  return all;
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_CHANNEL_H
