// `rt SCENE [switches]` as a function: load, build, render, write. The program's main() only
// parses the command line, calls this and turns errors into messages and exit codes.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "rt/app/options.h"
#include "rt/render/renderer.h"
#include "rt/window/picture_window.h"

namespace rt {

/// Where the run reports what a user should see; main() points these at stderr.
struct RunConsole {
    std::function<void(const std::string&)> warning;  ///< "rt: warning: ..."
    std::function<void(const std::string&)> note;     ///< informational lines
    std::function<void(const std::string&)> trace;    ///< -df parse trace, -dc columns
    std::function<void(const std::string&)> report;   ///< -p tables, on standard output
    /// Rows done of the total and the samples taken so far; called with 0 rows as the render
    /// starts, then after every row. May be empty.
    std::function<void(int rows_done, int rows_total, std::uint64_t samples)> progress;
    std::function<bool()> should_stop;  ///< Ctrl-C; may be empty
    /// Set by Ctrl-C: the render polls it inside the ray tree and stops within a fraction of a
    /// second. May be null.
    const std::atomic<bool>* stop_now = nullptr;
    /// -doi: where the octree session reads its commands and writes its answers (rt: standard
    /// input and output), and the prompt before each command (empty when no one types them).
    std::istream* commands = nullptr;
    std::ostream* answers = nullptr;
    std::string prompt;
    /// Opens the picture's window (rt: on a display, unless --no-window); empty, or returning
    /// null: no window. Not asked for -doi and -r, which draw no picture.
    std::function<std::unique_ptr<PictureWindow>(const WindowRequest&)> open_window;
    /// Called once the outputs are written, with the window still open (rt: waits for Enter when
    /// standard input is a terminal); empty: the window closes at once.
    std::function<void(const PictureWindow&)> keep_window_open;
};

/// How a run ended: Interrupted keeps the finished lines; a render stopped before its first line
/// was finished wrote nothing (InterruptedWithNothingKept).
enum class RunOutcome { Finished, Interrupted, InterruptedWithNothingKept };

/// The scene file a SCENE argument names: SCENE itself if it ends in ".scn", else SCENE.scn if
/// that exists, else SCENE if it is a file, else SCENE.scn (so that "cannot open" names it).
std::filesystem::path resolve_scene_path(const std::string& scene_argument);

/// The default output: the scene's name with ".gro", in the current folder.
std::filesystem::path default_gro_path(const std::string& scene_argument);
/// The .gro rt writes for `rt --model FILE`: FILE's stem with .gro, in the current folder
/// ("models/bunny.ply" -> "bunny.gro").
std::filesystem::path model_gro_path(const std::string& model_argument);

/// The part file of `--tile I/N` beside the .gro gro: "twocubes.gro" -> "twocubes.part-2-of-3.gro".
std::filesystem::path part_path(const std::filesystem::path& gro, PicturePart part);

/// The .gro a run writes: the scene's (or the model's) name, or with --tile its part file.
std::filesystem::path gro_output_path(const Options& options);

/// How a run renders its film once the scene and the accelerator are ready. By default the
/// renderer's render() on this process's threads; a cluster run (src/rt/cluster) shares the rows
/// among the processes of an MPI job. Returns nothing on a process that only helps: it writes
/// no output.
using RenderStep = std::function<std::optional<Film>(
    const Scene&, const Accelerator&, const RenderSettings&, RenderObserver&, RenderStatistics&)>;

/// Renders as the options say (with `step`, if given) and writes the outputs. Throws
/// rt::Error subclasses.
RunOutcome run(const Options& options, const RunConsole& console, const RenderStep& step = {});

}  // namespace rt
