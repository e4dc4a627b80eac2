// SPDX-License-Identifier: MIT
// Rendering on the ranks of an MPI communicator, with the bits of a render in one
// process.
//
// Opt-in: prism/prism.hpp does not include this header, since it needs MPI (Debian:
// libopenmpi-dev; CMake: prism::mpi). Call each function on every rank of the
// communicator, with the same arguments: they are collective.
//
// - Photons: each rank traces a contiguous share of each map's photon indices
//   (trace_photon_share; a photon's Sobol point and random stream come from its
//   index), the shares are all-gathered in rank order, and every rank builds the same
//   trees from the same photons as trace_photons would in one process.
// - Pixels: the image is cut into square tiles, dealt one at a time to whichever rank
//   asks next (a counter on rank 0, read and raised by MPI's one-sided fetch-and-add, so
//   a fast rank takes more), each rendered as render_sums renders it on the rank's
//   threads. A pixel's samples depend only on the seed, the pixel and the sample's
//   number, and its sums are exact (render/accumulation.hpp), so rank 0, adding the
//   tiles it receives into an empty image, has the single-process render's bits for
//   any number of ranks and any dealing.
// - Progressive photon mapping: its passes are dealt the same way, each rank summing
//   its own, and the ranks' sums added up on rank 0 by a reduction of 128-bit integers.
#pragma once

#include <prism/integrator/progressive.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/layers.hpp>
#include <prism/render/render.hpp>

#include <mpi.h>

#include <climits>
#include <limits>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace prism::mpi {

/// What a rank sent and received, in bytes, the tiles it rendered, and the seconds each
/// stage took it (added up over calls).
struct Traffic {
    std::uint64_t photon_bytes_sent = 0;     ///< its photons (and precomputed irradiance), to every other rank
    std::uint64_t photon_bytes_received = 0; ///< the other ranks' photons (and precomputed irradiance)
    std::uint64_t film_bytes = 0;            ///< its tiles' sums sent to rank 0 (rank 0: those it received), or its share of a reduction
    std::uint64_t tiles = 0;                 ///< tiles (or progressive passes) it rendered
    double trace_seconds = 0;                ///< tracing its share of the photons
    double photon_gather_seconds = 0;        ///< the all-gathers (with the wait for the slowest rank)
    double tree_seconds = 0;                 ///< building the maps' trees (every rank builds them all)
    double irradiance_seconds = 0;           ///< precomputing irradiance at its share of the global photons, and the all-gather
    double render_seconds = 0;               ///< rendering its tiles (or passes)
    double film_gather_seconds = 0;          ///< the film's gather (with the wait for the slowest rank) and, on rank 0, adding it up
};

namespace detail {

inline void check(int code, const char* call)
{
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(std::string("prism::mpi: ") + call + " failed: " + std::string(text, std::size_t(length)));
}

/// Seconds since the last lap (or the start), and since the start.
class Stopwatch {
public:
    double lap() noexcept
    {
        const double now = MPI_Wtime(), seconds = now - last_;
        last_ = now;
        return seconds;
    }
    [[nodiscard]] double total() const noexcept { return MPI_Wtime() - start_; }

private:
    double start_ = MPI_Wtime(), last_ = start_;
};

/// An element count MPI takes (an int), or a clear error.
inline int count_of(std::uint64_t n, const char* what)
{
    if (n > std::uint64_t(INT_MAX)) prism::detail::throw_invalid("prism::mpi: ", n, " ", what, " in one message, more than MPI's int count takes");
    return int(n);
}

/// Where each rank's part lies in a message of all ranks' parts (counts in elements).
struct Displacements {
    std::vector<int> counts, offsets;
    std::uint64_t total = 0;
};

inline Displacements displacements(const std::vector<unsigned long long>& counts, const char* what)
{
    Displacements d;
    for (const unsigned long long n : counts) {
        d.counts.push_back(count_of(n, what));
        d.offsets.push_back(count_of(d.total, what));
        d.total += n;
    }
    (void)count_of(d.total, what);
    return d;
}

/// A pixel's weight and exact sums as the messages carry them: each a 256-bit integer,
/// four 64-bit words, low first (a sum's two halves; the weight, then three zeros).
inline void append_pixel(std::vector<std::uint64_t>& words, const Accumulation& sums, int x, int y)
{
    words.insert(words.end(), {sums.weight(x, y), 0, 0, 0});
    for (std::size_t c = 0; c < sums.channels().size(); ++c) {
        const ExactSum s = sums.sum(x, y, c);
        words.insert(words.end(), {s.low().low(), s.low().high(), s.high().low(), s.high().high()});
    }
}

/// The exact sum in four words at `words` (append_pixel).
[[nodiscard]] inline ExactSum sum_at(const std::uint64_t* words) noexcept
{
    return ExactSum::from_bits(Int128::from_words(words[0], words[1]), Int128::from_words(words[2], words[3]));
}

/// Every rank's items, end to end in rank order, on every rank (the bytes each rank
/// sent and received added to traffic's photon counts).
template <class Item>
std::vector<Item> all_gather(MPI_Comm comm, const std::vector<Item>& mine, Traffic* traffic)
{
    static_assert(std::is_trivially_copyable_v<Item>);
    int size = 0;
    check(MPI_Comm_size(comm, &size), "MPI_Comm_size");
    const unsigned long long n = mine.size();
    std::vector<unsigned long long> counts(static_cast<std::size_t>(size), 0);
    check(MPI_Allgather(&n, 1, MPI_UNSIGNED_LONG_LONG, counts.data(), 1, MPI_UNSIGNED_LONG_LONG, comm), "MPI_Allgather");
    const Displacements parts = displacements(counts, "items");
    const std::uint64_t total = parts.total;
    // An item as one element of sizeof(Item) bytes: counts in items, not bytes.
    MPI_Datatype item{};
    check(MPI_Type_contiguous(int(sizeof(Item)), MPI_BYTE, &item), "MPI_Type_contiguous");
    check(MPI_Type_commit(&item), "MPI_Type_commit");
    std::vector<Item> all(total);
    const int code = MPI_Allgatherv(mine.data(), int(n), item, all.data(), parts.counts.data(), parts.offsets.data(), item, comm);
    MPI_Type_free(&item);
    check(code, "MPI_Allgatherv");
    if (traffic != nullptr) {
        traffic->photon_bytes_sent += std::uint64_t(n) * std::uint64_t(size - 1) * sizeof(Item);
        traffic->photon_bytes_received += (total - n) * sizeof(Item);
    }
    return all;
}

/// The tiles of `window`, tile x tile pixels (the last of a row or column shorter).
struct Tiles {
    PixelWindow window;
    int tile;
    std::int64_t across, down;

    Tiles(const PixelWindow& w, int t) : window(w), tile(t), across((std::int64_t(w.width()) - 1) / t + 1), down((std::int64_t(w.height()) - 1) / t + 1) {}
    [[nodiscard]] std::int64_t count() const noexcept { return across * down; }
    [[nodiscard]] PixelWindow operator[](std::int64_t i) const noexcept
    {
        const int x0 = window.x0 + int(i % across) * tile, y0 = window.y0 + int(i / across) * tile;
        return {x0, y0, std::min(x0 + tile, window.x1), std::min(y0 + tile, window.y1)};
    }
};

/// A shared counter on rank 0 that any rank raises by one and reads (the next tile or
/// pass to take).
class WorkCounter {
public:
    explicit WorkCounter(MPI_Comm comm)
    {
        int rank = 0;
        check(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
        check(MPI_Win_allocate(rank == 0 ? MPI_Aint(sizeof(std::int64_t)) : 0, int(sizeof(std::int64_t)), MPI_INFO_NULL, comm, &base_, &window_),
              "MPI_Win_allocate");
        if (rank == 0) *static_cast<std::int64_t*>(base_) = 0;
        // Every rank's counter is set before any rank takes a tile.
        check(MPI_Barrier(comm), "MPI_Barrier");
        check(MPI_Win_lock_all(0, window_), "MPI_Win_lock_all");
    }
    WorkCounter(const WorkCounter&) = delete;
    WorkCounter& operator=(const WorkCounter&) = delete;
    ~WorkCounter()
    {
        MPI_Win_unlock_all(window_);
        MPI_Win_free(&window_);
    }

    [[nodiscard]] std::int64_t next()
    {
        const std::int64_t one = 1;
        std::int64_t got = 0;
        check(MPI_Fetch_and_op(&one, &got, MPI_INT64_T, 0, 0, MPI_SUM, window_), "MPI_Fetch_and_op");
        check(MPI_Win_flush(0, window_), "MPI_Win_flush");
        return got;
    }

private:
    MPI_Win window_{};
    void* base_ = nullptr;
};

/// Deal `config`'s tiles over the ranks, render each with render_part(tile config) (an
/// Accumulation over the tile, with `channels`), and add them up on rank 0.
template <class RenderPart>
std::optional<Accumulation> render_dealt(MPI_Comm comm, const RenderConfig& config, int tile, const std::vector<std::string>& channels, Traffic* traffic,
                                         RenderPart&& render_part)
{
    int rank = 0, size = 0;
    check(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
    check(MPI_Comm_size(comm, &size), "MPI_Comm_size");
    // The same checks on every rank, before any communication: all refuse, or none.
    if (tile < 1) prism::detail::throw_invalid("prism::mpi tile must be >= 1, got ", tile);
    const PixelWindow window = prism::detail::render_window(config);
    (void)prism::detail::render_passes(config);
    // A budget per tile would give the tiles different samples.
    if (prism::detail::render_seconds(config) != 0.0)
        prism::detail::throw_invalid("prism::mpi renders every sample of the range: RenderConfig seconds must be 0, got ", config.seconds);
    const Tiles tiles(window, tile);

    // Each tile's record: its number, the values it rejected, whether a sum overflowed,
    // then its pixels in rows (append_pixel).
    Stopwatch clock;
    std::vector<std::uint64_t> mine;
    const std::size_t words_per_pixel = 4 * (1 + channels.size());
    {
        WorkCounter counter(comm);
        for (std::int64_t t = counter.next(); t < tiles.count(); t = counter.next()) {
            RenderConfig part = config;
            part.crop = tiles[t];
            part.progress = false; // a tile's progress says nothing of the image's
            const Accumulation sums = render_part(part);
            mine.insert(mine.end(), {std::uint64_t(t), std::uint64_t(sums.rejected()), std::uint64_t(sums.overflowed())});
            for (int y = part.crop.y0; y < part.crop.y1; ++y)
                for (int x = part.crop.x0; x < part.crop.x1; ++x) append_pixel(mine, sums, x, y);
            if (traffic != nullptr) ++traffic->tiles;
        }
    }

    if (traffic != nullptr) traffic->render_seconds += clock.lap();

    // Rank 0 gathers the records and adds each tile into the image, which begins empty:
    // exact sums, so the same bits as one process's.
    const unsigned long long n = mine.size();
    std::vector<unsigned long long> counts(std::size_t(rank == 0 ? size : 0));
    check(MPI_Gather(&n, 1, MPI_UNSIGNED_LONG_LONG, counts.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, comm), "MPI_Gather");
    const Displacements parts = displacements(counts, "film words");
    const std::uint64_t total = parts.total;
    std::vector<std::uint64_t> all(rank == 0 ? total : 0);
    check(MPI_Gatherv(mine.data(), count_of(n, "film words"), MPI_UINT64_T, all.data(), parts.counts.data(), parts.offsets.data(), MPI_UINT64_T, 0,
                      comm),
          "MPI_Gatherv");
    if (traffic != nullptr) traffic->film_bytes += (rank == 0 ? total - n : n) * sizeof(std::uint64_t);
    if (rank != 0) {
        if (traffic != nullptr) traffic->film_gather_seconds += clock.lap();
        return std::nullopt;
    }

    Accumulation image(config.width, config.height, window, channels);
    std::vector<ExactSum> pixel(channels.size());
    std::size_t at = 0;
    std::uint64_t rejected = 0;
    bool overflowed = false;
    std::int64_t received = 0;
    while (at < all.size()) {
        const PixelWindow w = tiles[std::int64_t(all[at])];
        rejected += all[at + 1];
        overflowed |= all[at + 2] != 0;
        at += 3;
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) {
                for (std::size_t c = 0; c < channels.size(); ++c) pixel[c] = sum_at(&all[at + 4 + 4 * c]);
                image.add(x, y, pixel, all[at]);
                at += words_per_pixel;
            }
        ++received;
    }
    PRISM_ASSERT(at == all.size());
    if (received != tiles.count())
        throw std::runtime_error("prism::mpi: rank 0 received " + std::to_string(received) + " of " + std::to_string(tiles.count()) + " tiles");
    if (overflowed) prism::detail::throw_invalid("prism::mpi: a tile's sums overflowed: the image would be wrong");
    image.reject(std::size_t(rejected));
    if (traffic != nullptr) traffic->film_gather_seconds += clock.lap();
    return image;
}

/// 256-bit integers (four 64-bit words, low first: append_pixel) summed by MPI_Reduce.
/// An overflow, or an operand that overflowed before, gives the lowest value, which no
/// exact sum or weight can be (their magnitudes stay far below 2^255): rank 0 then
/// refuses the result.
inline constexpr ExactSum overflowed_sum = ExactSum::from_bits(Int128{}, Int128::from_words(0, std::uint64_t(1) << 63));

inline void add_sums(void* in, void* inout, int* count, MPI_Datatype*)
{
    auto* a = static_cast<std::uint64_t*>(in);
    auto* b = static_cast<std::uint64_t*>(inout);
    for (int i = 0; i < *count; ++i, a += 4, b += 4) {
        const ExactSum x = sum_at(a), y = sum_at(b);
        ExactSum sum = x;
        if (x == overflowed_sum || y == overflowed_sum || !sum.add(y)) sum = overflowed_sum;
        b[0] = sum.low().low();
        b[1] = sum.low().high();
        b[2] = sum.high().low();
        b[3] = sum.high().high();
    }
}

/// Every rank's `sums` (the same window and channels on each) added up on rank 0, by a
/// reduction of 256-bit integers: the exact sums of every share.
inline std::optional<Accumulation> reduce_sums(MPI_Comm comm, const Accumulation& sums, Traffic* traffic)
{
    int rank = 0;
    check(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
    const PixelWindow& w = sums.window();
    const std::size_t channels = sums.channels().size(), per_pixel = 1 + channels;
    std::vector<std::uint64_t> mine, all;
    mine.reserve(4 * per_pixel * w.area());
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) append_pixel(mine, sums, x, y);
    if (rank == 0) all.resize(mine.size());
    MPI_Datatype int256{};
    MPI_Op sum{};
    check(MPI_Type_contiguous(4, MPI_UINT64_T, &int256), "MPI_Type_contiguous");
    check(MPI_Type_commit(&int256), "MPI_Type_commit");
    check(MPI_Op_create(&add_sums, 1, &sum), "MPI_Op_create");
    const int code = MPI_Reduce(mine.data(), all.data(), count_of(mine.size() / 4, "256-bit sums"), int256, sum, 0, comm);
    MPI_Op_free(&sum);
    MPI_Type_free(&int256);
    check(code, "MPI_Reduce");
    unsigned long long rejected = sums.rejected(), total_rejected = 0;
    int overflowed = sums.overflowed() ? 1 : 0, any_overflowed = 0;
    check(MPI_Reduce(&rejected, &total_rejected, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, 0, comm), "MPI_Reduce");
    check(MPI_Reduce(&overflowed, &any_overflowed, 1, MPI_INT, MPI_LOR, 0, comm), "MPI_Reduce");
    if (traffic != nullptr) traffic->film_bytes += mine.size() * sizeof(std::uint64_t);
    if (rank != 0) return std::nullopt;

    Accumulation image(sums.width(), sums.height(), w, sums.channels());
    std::vector<ExactSum> pixel(channels);
    const auto item = [&](std::size_t i) { return sum_at(&all[4 * i]); };
    std::size_t at = 0;
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x, at += per_pixel) {
            bool bad = any_overflowed != 0;
            for (std::size_t i = at; i < at + per_pixel; ++i) bad |= item(i) == overflowed_sum;
            const ExactSum weight = item(at);
            if (bad || !(weight.high() == Int128{}) || weight.low().high() != 0) // a weight is an unsigned 64-bit integer
                prism::detail::throw_invalid("prism::mpi: the ranks' sums overflowed: the image would be wrong");
            for (std::size_t c = 0; c < channels; ++c) pixel[c] = item(at + 1 + c);
            image.add(x, y, pixel, weight.low().low());
        }
    image.reject(std::size_t(total_rejected));
    return image;
}

} // namespace detail

[[nodiscard]] inline int rank(MPI_Comm comm = MPI_COMM_WORLD)
{
    int r = 0;
    detail::check(MPI_Comm_rank(comm, &r), "MPI_Comm_rank");
    return r;
}

[[nodiscard]] inline int size(MPI_Comm comm = MPI_COMM_WORLD)
{
    int s = 0;
    detail::check(MPI_Comm_size(comm, &s), "MPI_Comm_size");
    return s;
}

/// trace_photons over the ranks of `comm`: every rank returns the maps one process
/// would trace, having traced 1 / size of the photons.
template <class SceneT, class Air = StraightAir>
[[nodiscard]] PhotonMaps trace_photons(MPI_Comm comm, const SceneT& scene, const PhotonTracerConfig& config = {}, const Air& air = {},
                                       std::size_t pass = 0, Traffic* traffic = nullptr)
{
    detail::Stopwatch clock;
    PhotonShare mine = trace_photon_share(scene, config, air, pass, std::size_t(rank(comm)), std::size_t(size(comm)));
    const double traced = clock.lap();
    std::vector<Photon> global = detail::all_gather(comm, mine.global, traffic), caustic = detail::all_gather(comm, mine.caustic, traffic);
    const double gathered = clock.lap();
    PhotonMaps maps;
    maps.global = PhotonMap(std::move(global), config.threads);
    maps.caustic = PhotonMap(std::move(caustic), config.threads);
    if constexpr (SceneT::has_scattering_media || air_scatters<Air>) {
        std::vector<Photon> volume = detail::all_gather(comm, mine.volume, traffic);
        if (!volume.empty()) maps.volume = PhotonMap(std::move(volume), config.threads);
    }
    if (traffic != nullptr) {
        traffic->trace_seconds += traced;
        traffic->photon_gather_seconds += gathered;
        traffic->tree_seconds += clock.lap();
    }
    return maps;
}

/// PhotonMap::precompute_irradiance<K> over the ranks of `comm`: each estimates a share
/// of the samples, and every rank's map receives them all (the same values as in one
/// process). PhotonMapper<S>::precomputed_k and precomputed_stride are the mapper's.
template <std::size_t K>
void precompute_irradiance(MPI_Comm comm, PhotonMap& map, std::size_t stride, unsigned threads = 1, Traffic* traffic = nullptr)
{
    detail::Stopwatch clock;
    std::vector<Photon> samples = map.irradiance_samples(stride);
    const std::size_t n = samples.size(), r = std::size_t(rank(comm)), p = std::size_t(size(comm));
    const std::size_t first = n / p * r + n % p * r / p, last = n / p * (r + 1) + n % p * (r + 1) / p;
    std::vector<PrecomputedIrradiance> mine(last - first);
    prism::detail::parallel_for(mine.size(), threads, [&](std::size_t i) { mine[i] = map.precomputed_estimate<K>(samples[first + i]); });
    map.set_precomputed_irradiance(std::move(samples), detail::all_gather(comm, mine, traffic), threads);
    if (traffic != nullptr) traffic->irradiance_seconds += clock.lap();
}

/// render_sums over the ranks of `comm`: rank 0 returns the sums, bit for bit those of
/// render_sums in one process; the other ranks return nullopt. An integrator of camera
/// rays is dealt `tile` x `tile` pixels at a time (each rendered on config.threads
/// threads); one of passes (PassEstimator) is dealt one pass at a time to whichever rank
/// asks next (its photons or light paths traced there), every rank's passes summed exactly
/// and the shares added up on rank 0 by a reduction of 128-bit sums. A time budget
/// (RenderConfig::seconds) would make the pass count depend on the machines: it is
/// refused.
template <Integrator I>
[[nodiscard]] std::optional<Accumulation> render_sums(MPI_Comm comm, const Camera<typename I::scalar_type>& camera, const I& integrator,
                                                      const RenderConfig& config = {}, int tile = 64, Traffic* traffic = nullptr)
{
    if constexpr (RayEstimator<I>) {
        return detail::render_dealt(comm, config, tile, {"R", "G", "B"}, traffic,
                                    [&](const RenderConfig& part) { return prism::render_sums(camera, integrator, part); });
    } else {
        if (prism::detail::render_seconds(config) != 0.0)
            prism::detail::throw_invalid("prism::mpi::render_sums takes a pass count, not a time budget: RenderConfig seconds must be 0, got ", config.seconds);
        const PassRange passes = prism::detail::render_passes(config);
        (void)camera.rays(config.width, config.height); // every rank refuses alike, before any pass
        if constexpr (requires { integrator.check_passes(config); }) integrator.check_passes(config);
        detail::Stopwatch clock;
        Accumulation mine(config.width, config.height, prism::detail::render_window(config));
        {
            detail::WorkCounter counter(comm);
            for (std::int64_t k = counter.next(); k < std::int64_t(passes.count()); k = counter.next()) {
                RenderConfig one = config;
                one.passes = {passes.first + std::uint64_t(k), passes.first + std::uint64_t(k) + 1};
                one.progress = false;
                prism::render_into(mine, camera, integrator, one);
                if (traffic != nullptr) ++traffic->tiles;
            }
        }
        if (traffic != nullptr) traffic->render_seconds += clock.lap();
        std::optional<Accumulation> sums = detail::reduce_sums(comm, mine, traffic);
        if (traffic != nullptr) traffic->film_gather_seconds += clock.lap();
        return sums;
    }
}

/// render_layers (render/layers.hpp) over the ranks of `comm`, as render_sums.
template <Integrator I>
[[nodiscard]] std::optional<Accumulation> render_layers(MPI_Comm comm, const Camera<typename I::scalar_type>& camera, const I& integrator,
                                                        const RenderConfig& config = {}, int tile = 64, Traffic* traffic = nullptr)
{
    if constexpr (RayEstimator<I>) {
        return detail::render_dealt(comm, config, tile, layer_channels<I>(), traffic,
                                    [&](const RenderConfig& part) { return prism::render_layers(camera, integrator, part); });
    } else {
        return render_sums(comm, camera, integrator, config, tile, traffic);
    }
}

} // namespace prism::mpi
