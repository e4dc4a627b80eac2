// SPDX-License-Identifier: MIT
// mpi_render: cornell_caustics' photon-mapped Cornell box rendered by the ranks of an MPI
// job (distributed/mpi.hpp): each rank traces its share of the photons, the maps are
// all-gathered, tiles are dealt to whichever rank asks next, and rank 0 writes the
// image, the same bits as `cornell_caustics` with the same flags writes in one process.
//
//   mpirun -np 4 mpi_render --width 256 --height 256 --threads 1 --out images
//
// It takes cornell_caustics' flags (--method direct, gather, cache, progressive, reference, bdpt or vcm, whose
// passes are dealt to the ranks instead of tiles) and --tile N, the side of the square of
// pixels dealt at a time. With --method cache every rank builds
// the whole irradiance cache (its records are found in the order one process finds
// them: sharing them is the next step). Rank 0 prints the stages' times and each
// rank's traffic.
#include "cli.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>
#include <prism/distributed/mpi.hpp>

#include <chrono>
#include <cstdio>
#include <vector>

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int tile = 64;
    bool communicating = false;
    // --tile is this program's own; the rest are cornell_caustics'.
    std::vector<char*> args;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const int code = examples::run(rank == 0 ? stderr : nullptr, [&] {
        for (int i = 0; i < argc; ++i) {
            if (std::string_view(argv[i]) == "--tile") {
                if (i + 1 >= argc) throw std::invalid_argument("--tile expects an integer in [1, 65536], got nothing");
                tile = examples::parse_integer<int>("--tile", argv[++i], 1, 1 << 16);
            } else {
                args.push_back(argv[i]);
            }
        }
        for (char* arg : args)
            if (std::string_view(arg) == "--help" || std::string_view(arg) == "-h")
                std::printf("mpi_render: cornell_caustics' flags, and\n  --tile N      side of the square of pixels dealt to a rank at a time (default 64)\n\n");
        examples::Options options;
        options.images = {"cornell_caustics"}; // checked before rendering, written together after
        options.render.spp = 4;
        if (!examples::parse(int(args.size()), args.data(), options, "the Cornell box with photon-mapped caustics, on MPI ranks",
                             {.photons = true}))
            return 0;
        options.program = "cornell_caustics"; // the same settings as that program's, for prism_merge
        if (!options.render.passes.empty() || options.first_pass != 0)
            throw std::invalid_argument("--passes A:B is for one machine's part: mpi_render renders every pass");
        const int ranks = prism::mpi::size();
        const auto scene = scenes::cornell_scene<float>(!options.povray_light);
        const auto camera = scenes::cornell_camera<float>();
        const auto config = examples::photon_mapper_config<std::remove_cvref_t<decltype(scene)>>(options);

        // Everything above fails alike on every rank (the same flags); from here on a
        // rank that fails leaves the others waiting, and the job is aborted.
        communicating = true;
        const auto start = std::chrono::steady_clock::now();
        const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
        prism::mpi::Traffic traffic;
        // Each rank's traffic and stage times, printed by rank 0 (every rank calls it).
        const auto report = [&](const prism::mpi::Traffic& t, double done) {
            constexpr int fields = 11;
            const double mine[fields] = {double(t.photon_bytes_sent), double(t.photon_bytes_received), double(t.film_bytes), double(t.tiles),
                                         t.trace_seconds, t.photon_gather_seconds, t.tree_seconds, t.irradiance_seconds, t.render_seconds,
                                         t.film_gather_seconds, done};
            std::vector<double> all(rank == 0 ? fields * std::size_t(ranks) : 0);
            MPI_Gather(mine, fields, MPI_DOUBLE, all.data(), fields, MPI_DOUBLE, 0, MPI_COMM_WORLD);
            if (rank != 0) return;
            for (int r = 0; r < ranks; ++r) {
                const double* v = &all[fields * std::size_t(r)];
                std::printf("  rank %d: photons sent %.0f B, received %.0f B; film %.0f B; %.0f tiles; trace %.4f s, photon gather %.4f s, trees %.4f s, "
                            "irradiance %.4f s, render %.4f s, film gather %.4f s; done at %.3f s\n",
                            r, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10]);
            }
        };
        if (options.method == "reference") {
            // Passes (a camera sample in every pixel and as many light paths) dealt to the ranks.
            const prism::Reference reference(scene, {.max_diffuse_bounces = options.povray_light ? 0 : 256});
            std::optional<prism::Accumulation> result =
                prism::mpi::render_sums(MPI_COMM_WORLD, camera, reference, examples::pass_render_config(options), tile, &traffic);
            const double done = seconds();
            report(traffic, done);
            if (rank != 0) return 0;
            std::printf("cornell_caustics on %d ranks: reference, %d passes, total %.3f s\n", ranks, options.render.spp, done);
            examples::save(examples::Rendered{"cornell_caustics", std::move(*result), done}, options, true);
            return 0;
        }
        if (options.method == "bdpt" || options.method == "vcm") {
            // Passes (a camera path in every pixel and as many light paths) dealt to the ranks.
            const prism::Bidirectional estimator(scene, {.method = options.method == "vcm" ? prism::BidirectionalMethod::vcm : prism::BidirectionalMethod::bdpt});
            std::optional<prism::Accumulation> result =
                prism::mpi::render_sums(MPI_COMM_WORLD, camera, estimator, examples::pass_render_config(options), tile, &traffic);
            const double done = seconds();
            report(traffic, done);
            if (rank != 0) return 0;
            std::printf("cornell_caustics on %d ranks: %s, %d passes, total %.3f s\n", ranks, options.method.c_str(), options.render.spp, done);
            examples::save(examples::Rendered{"cornell_caustics", std::move(*result), done}, options, true);
            return 0;
        }
        if (options.method == "progressive") {
            // Passes dealt to the ranks, each tracing its own photons.
            using S = std::remove_cvref_t<decltype(scene)>;
            const prism::ProgressivePhotonMapper<S> progressive(scene, examples::progressive_config<S>(options));
            std::optional<prism::Accumulation> result =
                prism::mpi::render_sums(MPI_COMM_WORLD, camera, progressive, examples::pass_render_config(options), tile, &traffic);
            const double done = seconds();
            report(traffic, done);
            if (rank != 0) return 0;
            std::printf("cornell_caustics on %d ranks: progressive photon mapping, %zu passes, total %.3f s\n", ranks, options.passes, done);
            examples::save(examples::Rendered{"cornell_caustics", std::move(*result), done}, options, true);
            return 0;
        }
        prism::PhotonMaps maps = prism::mpi::trace_photons(MPI_COMM_WORLD, scene, config.tracing, prism::StraightAir{}, 0, &traffic);
        using Mapper = prism::PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
        if (config.gather_rays > 0)
            prism::mpi::precompute_irradiance<Mapper::precomputed_k>(MPI_COMM_WORLD, maps.global, Mapper::precomputed_stride, config.tracing.threads,
                                                                    &traffic);
        const double traced = seconds();
        Mapper mapper(scene, config, std::move(maps));
        if (options.method == "cache") mapper.cache_irradiance(camera, options.render);
        const double cached = seconds();
        const bool layers = options.exr || options.part;
        std::optional<prism::Accumulation> sums = layers ? prism::mpi::render_layers(MPI_COMM_WORLD, camera, mapper, options.render, tile, &traffic)
                                                         : prism::mpi::render_sums(MPI_COMM_WORLD, camera, mapper, options.render, tile, &traffic);
        const double rendered = seconds();

        report(traffic, rendered);
        if (rank != 0) return 0;
        std::printf("cornell_caustics on %d ranks: photon maps %.3f s, irradiance cache %.3f s, render %.3f s, total %.3f s\n", ranks, traced,
                    cached - traced, rendered - cached, rendered);
        examples::save(examples::Rendered{"cornell_caustics", std::move(*sums), rendered}, options, true);
        return 0;
    });
    // A rank that failed may leave the others waiting in a collective: after they began
    // communicating, or before, where its failure was its own (every rank checks the same
    // flags, but not at the same instant). One process alone just ends.
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (code != 0 && (communicating || ranks > 1)) MPI_Abort(MPI_COMM_WORLD, code);
    MPI_Finalize();
    return code;
}
