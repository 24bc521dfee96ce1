/// @file app/mpi/mpi_main.cpp
/// @brief `kerf-mpi render …`: `kerf render` across MPI processes (`mpirun -n N kerf-mpi
/// render model.kerf -o out.exr`, same options). Rank 0 reads the model file and broadcasts
/// its text; every rank compiles it (includes and meshes are read by each rank, relative to
/// the model's path: they must be on a file system all ranks see). Tiles are handed out by a
/// shared counter on rank 0 (MPI one-sided fetch-and-add), so a fast rank takes more; every
/// rank, rank 0 included, renders with its own threads. The tiles are gathered on rank 0,
/// which sums filtered tiles in the order a single process does (bit-identical image) and
/// writes the outputs atomically. Every step ends with all ranks agreeing on an exit code,
/// so a bad option or model stops all of them (exit 2) with the message printed once.
#include "app/cli_render.h"
#include "app/cli_slice.h"
#include "app/exit_codes.h"
#include "app/frame_sequence.h"
#include "app/model_loader.h"
#include "app/mpi/tile_exchange.h"
#include "app/render_setup.h"
#include "app/stats_report.h"
#include "lang/compile.h"
#include "lang/diagnostic.h"
#include "lang/openscad_csg.h"
#include "lang/source.h"

#include <mpi.h>
#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <sstream>
#include <thread>

namespace {

using namespace kerf;
using namespace kerf::app;

struct Ranks {
    int rank = 0;
    int size = 1;
};

/// Runs `step` on every rank and returns the highest exit code any rank's step gave. A
/// failure is printed by rank 0, or, when rank 0's step succeeded, by the ranks that failed.
int agreed(const Ranks& r, const std::function<void()>& step) {
    int code = kExitSuccess;
    std::string message;
    try {
        step();
    } catch (const UsageError& e) {
        code = kExitUsage;
        // An empty message: already printed (a model's diagnostics, by rank 0).
        if (e.what()[0] != '\0') message = std::string("kerf: error: ") + e.what() + "\n";
    } catch (const FileWriteError& e) {
        code = kExitFailure;
        message = std::string("kerf: error: ") + e.what() + "\n";
    } catch (const std::exception& e) {
        code = kExitFailure;
        message = std::string("kerf: error: ") + e.what() + "\n";
    }
    int mine[2] = {code, r.rank == 0 ? code : 0}, all[2] = {0, 0};
    MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (!message.empty() && (r.rank == 0 || all[1] == kExitSuccess)) {
        if (r.rank != 0) message = "kerf-mpi: rank " + std::to_string(r.rank) + ": " + message;
        std::cerr << message << std::flush;
    }
    return all[0];
}

/// Rank 0's model text on every rank; throws UsageError (on rank 0) when it cannot be read.
std::string broadcastModel(const Ranks& r, const std::string& path, int& code) {
    std::string text;
    code = agreed(r, [&] {
        if (r.rank != 0) return;
        std::string why = sourceFileProblem(path);
        std::optional<std::string> bytes;
        if (why.empty()) bytes = readFileBytes(path, why);
        if (!bytes) throw UsageError("cannot read model file '" + path + "': " + why);
        text = std::move(*bytes);
    });
    if (code != kExitSuccess) return text;
    uint64_t size = text.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    text.resize(size);
    for (uint64_t at = 0; at < size;) {  // counts are ints: in pieces of at most 1 GiB
        const int piece = int(std::min<uint64_t>(size - at, uint64_t(1) << 30));
        MPI_Bcast(text.data() + at, piece, MPI_CHAR, 0, MPI_COMM_WORLD);
        at += uint64_t(piece);
    }
    return text;
}

/// The compiled scene; diagnostics as `kerf render` prints them, on rank 0 only.
std::optional<Scene> compileModel(const Ranks& r, const std::string& path, const std::string& text,
                                  bool quiet, const SequenceFrame& frame) {
    DiagnosticSink sink;
    std::optional<Scene> scene =
        isOpenScadCsgPath(path)
            ? compileOpenScadString(text, path, sink, processAssets())
            : compileString(text, path, sink, processAssets(), EvalLimits{}, frame);
    if (r.rank == 0 && !sink.diagnostics().empty()) std::cerr << sink.format(!quiet);
    if (!scene) {
        if (r.rank == 0 && !sink.hasErrors())
            std::cerr << "kerf: error: '" << path << "' could not be compiled\n";
        // Printed above on rank 0; another rank's own failure (an include it cannot read)
        // is printed by it when rank 0 compiled the model.
        throw UsageError(r.rank == 0 ? std::string()
                                     : "the model failed here:\n" + sink.format(false));
    }
    return scene;
}

/// A counter in rank 0's memory that every rank increments atomically.
class SharedCounter {
public:
    SharedCounter() {
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Win_allocate(rank == 0 ? MPI_Aint(sizeof(int)) : 0, sizeof(int), MPI_INFO_NULL,
                         MPI_COMM_WORLD, &mBase, &mWindow);
        if (rank == 0) {
            MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, mWindow);
            *mBase = 0;
            MPI_Win_unlock(0, mWindow);
        }
        MPI_Barrier(MPI_COMM_WORLD);
    }
    ~SharedCounter() { MPI_Win_free(&mWindow); }
    SharedCounter(const SharedCounter&) = delete;
    SharedCounter& operator=(const SharedCounter&) = delete;

    int next() {
        const int one = 1;
        int value = 0;
        MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, mWindow);
        MPI_Fetch_and_op(&one, &value, MPI_INT, 0, 0, MPI_SUM, mWindow);
        MPI_Win_unlock(0, mWindow);
        return value;
    }

private:
    int* mBase = nullptr;
    MPI_Win mWindow = MPI_WIN_NULL;
};

/// Every rank's packed tiles, on rank 0 (empty elsewhere).
std::vector<std::vector<char>> gatherPacks(const Ranks& r, const std::vector<char>& mine) {
    const int64_t size = int64_t(mine.size());
    std::vector<int64_t> sizes(size_t(r.size), 0);
    MPI_Gather(&size, 1, MPI_INT64_T, sizes.data(), 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
    std::vector<std::vector<char>> packs;
    if (r.rank == 0) {
        packs.resize(size_t(r.size));
        packs[0] = mine;
        for (int k = 1; k < r.size; ++k) {
            packs[size_t(k)].resize(size_t(sizes[size_t(k)]));
            for (int64_t at = 0; at < sizes[size_t(k)];) {
                const int piece = int(std::min<int64_t>(sizes[size_t(k)] - at, int64_t(1) << 30));
                MPI_Recv(packs[size_t(k)].data() + at, piece, MPI_CHAR, k, 0, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
                at += piece;
            }
        }
    } else {
        for (int64_t at = 0; at < size;) {
            const int piece = int(std::min<int64_t>(size - at, int64_t(1) << 30));
            MPI_Send(mine.data() + at, piece, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
            at += piece;
        }
    }
    return packs;
}

/// One image (of a sequence, or alone): its tiles shared out across the ranks, gathered and
/// written by rank 0.
int renderImage(const Ranks& r, const RenderCommandLine& line) {
    RenderSetup setup;
    int code = agreed(r, [&] { setup = setUpRender(line, r.rank == 0); });
    if (code != kExitSuccess) return code;
    const std::string text = broadcastModel(r, line.model, code);
    if (code != kExitSuccess) return code;
    std::optional<Scene> scene;
    const auto compileStart = std::chrono::steady_clock::now();
    code = agreed(r, [&] {
        scene = compileModel(r, line.model, text, line.quiet || r.rank != 0,
                             line.frame.value_or(SequenceFrame{}));
        applySetup(setup, *scene);
    });
    if (code != kExitSuccess) return code;
    const double secondsCompile =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - compileStart).count();

    RenderResult local;
    {
        SharedCounter counter;
        setup.options.nextTile = [&counter] { return counter.next(); };
        local = render(*scene, setup.options);
    }  // every rank has taken its last tile before the counter is freed (collectively)
    const std::vector<char> mine = mpi::packTiles(local);
    const std::vector<std::vector<char>> packs = gatherPacks(r, mine);
    const int64_t tileCount = int64_t(local.tiles.size());
    std::vector<int64_t> tilesByRank(size_t(r.size), 0);
    MPI_Gather(&tileCount, 1, MPI_INT64_T, tilesByRank.data(), 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
    // The ray and sample counts of all ranks (the other statistics are rank 0's own).
    RenderStats& st = local.stats;
    uint64_t counts[5] = {st.cameraRays, st.shadowRays, st.reflectionRays, st.refractionRays,
                          st.samplesTaken};
    uint64_t sums[5] = {0, 0, 0, 0, 0};
    MPI_Reduce(counts, sums, 5, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    st.cameraRays = sums[0];
    st.shadowRays = sums[1];
    st.reflectionRays = sums[2];
    st.refractionRays = sums[3];
    st.samplesTaken = sums[4];

    code = agreed(r, [&] {
        if (r.rank != 0) return;
        const RenderResult full = mpi::assembleTiles(local, packs);
        writeRenderOutputs(full, setup.plan);
        if (line.stats) {
            RunReport report;
            report.width = full.fullWidth;
            report.height = full.fullHeight;
            report.spp = full.stats.samplesPerPixel;
            report.threads = setup.options.threads > 0
                                 ? setup.options.threads
                                 : int(std::max(1u, std::thread::hardware_concurrency()));
            report.render = full.stats;  // rays and samples of all ranks; the rest rank 0's
            report.secondsCompile = secondsCompile;
            printStats(report, std::cerr);
            // What the distribution cost: tiles per rank and the bytes gathered.
            int64_t bytes = 0, tiles = 0;
            for (const std::vector<char>& p : packs) bytes += int64_t(p.size());
            std::cerr << "kerf-mpi: " << r.size << " ranks; tiles by rank:";
            for (int64_t t : tilesByRank) {
                std::cerr << " " << t;
                tiles += t;
            }
            std::cerr << "; gathered " << bytes << " bytes, " << (tiles > 0 ? bytes / tiles : 0)
                      << " per tile\n";
        }
    });
    return code;
}

/// `kerf-mpi slice`: a stack's layers dealt out across the ranks (every size-th layer from
/// the rank's own), each rank writing its own layers' files; one plane is sliced by rank 0.
/// The model is compiled on rank 0 first, so its diagnostics are printed once.
int sliceStack(const Ranks& r, SliceCommandLine line) {
    int code = agreed(r, [&] {
        if (r.rank == 0 && !loadModel(line.model, std::cerr, line.quiet)) throw UsageError("");
    });
    if (code != kExitSuccess) return code;
    if (r.rank != 0) {
        line.quiet = true;
        line.stats = false;
    }
    line.part = r.rank;
    line.parts = r.size;
    int sliced = kExitSuccess;
    code = agreed(r, [&] {
        if (r.rank == 0 || !line.stack.empty()) sliced = runSlice(line);
    });
    return code != kExitSuccess ? code : sliced;
}

int run(const Ranks& r, int argc, char** argv) {
    CLI::App cli(
        "kerf-mpi: kerf render and kerf slice --stack across MPI processes (mpirun -n N "
        "kerf-mpi render FILE …); the image is the same, bit for bit, as kerf render's, and a "
        "stack's layers are shared out",
        "kerf-mpi");
    cli.require_subcommand(1);
    RenderCommandLine line;
    addRenderCommand(cli, line);
    SliceCommandLine sliceLine;
    CLI::App* sliceCmd = addSliceCommand(cli, sliceLine);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return r.rank == 0 ? cli.exit(e) : kExitSuccess;
    } catch (const CLI::ParseError& e) {
        if (r.rank == 0)
            std::cerr << "kerf: error: " << e.what() << "\n"
                      << "Run 'kerf-mpi render --help' for usage.\n";
        return kExitUsage;  // every rank parsed the same arguments
    }

    if (sliceCmd->parsed()) return sliceStack(r, sliceLine);
    if (!wantsFrameSequence(line)) return renderImage(r, line);
    // A sequence: every rank runs the same frame loop (the same arguments, so the same frames
    // and checks), and each frame's tiles are shared out as one image's are. Only rank 0 speaks.
    RenderCommandLine loop = line;
    if (r.rank != 0) {
        loop.quiet = true;
        loop.stats = false;
    }
    int code = kExitSuccess;
    const int checked = agreed(r, [&] {
        code =
            renderFrames(loop, [&](const RenderCommandLine& one) { return renderImage(r, one); });
    });
    return checked != kExitSuccess ? checked : code;
}

}  // namespace

int main(int argc, char** argv) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
    Ranks r;
    MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &r.size);
    int code = kExitFailure;
    {
        tbb::task_scheduler_handle workers{tbb::attach{}};
        try {
            if (provided < MPI_THREAD_SERIALIZED)
                throw std::runtime_error(
                    "this MPI library cannot be called from several threads "
                    "(MPI_THREAD_SERIALIZED)");
            code = run(r, argc, argv);
        } catch (const std::exception& e) {
            // A failure inside the render or the gather: the other ranks may be waiting.
            std::cerr << "kerf-mpi: rank " << r.rank << ": error: " << e.what() << "\n";
            MPI_Abort(MPI_COMM_WORLD, kExitFailure);
        }
        tbb::finalize(workers, std::nothrow);
    }
    MPI_Finalize();
    return code;
}
