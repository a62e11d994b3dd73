// How far a render has got, for a person watching it: lines done, samples per second, time spent
// and time left. ProgressFigures is the arithmetic and the wording, with no clock and no stream,
// so a window's title can use it as well; ProgressReport decides when to print and how: on a
// terminal a bar redrawn in place at most ten times a second, elsewhere a plain line every few
// seconds. The renderer's row events feed it (RunConsole::progress); rt's main() owns it.
#pragma once

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace rt {

/// A render's progress at one moment.
struct ProgressFigures {
    int rows_done = 0;
    int rows_total = 0;
    std::uint64_t samples = 0;     ///< eye rays (pixel samples) taken so far
    double elapsed_seconds = 0.0;  ///< since the render started

    double fraction() const;
    double samples_per_second() const;
    /// Elapsed time scaled by the rows still to do; none before the first row is done.
    std::optional<double> seconds_left() const;
};

/// "0:07", "12:34", "1:02:03": minutes and seconds, with hours when there are any.
std::string format_duration(double seconds);
/// "950", "45.6k", "1.23M": a rate with three significant figures.
std::string format_rate(double per_second);

/// One line for a terminal, about 75 characters wide:
/// "[#########...........]  123/400 lines  45.6k samples/s  0:12 elapsed  0:30 left".
std::string progress_bar_text(const ProgressFigures& figures);
/// One line for a log: "123 of 400 lines (30 %), 45.6k samples/s, 0:12 elapsed, 0:30 left".
std::string progress_line_text(const ProgressFigures& figures);

class ProgressReport {
public:
    /// A bar redrawn in place (a terminal), or a plain line now and then (a file or a pipe).
    enum class Style { Bar, Lines };
    /// Seconds on a clock that never goes back (std::chrono::steady_clock in rt).
    using Clock = std::function<double()>;

    static constexpr double kBarInterval = 0.1;   ///< at most ten redraws a second
    static constexpr double kLineInterval = 5.0;  ///< a plain line every five seconds

    /// Every line printed starts with `prefix` ("rt: ").
    ProgressReport(std::ostream& out, Style style, Clock clock, std::string prefix = "rt: ");
    /// A bar left on screen (a render that stopped by an error) keeps its line: what is printed
    /// next starts on a line of its own.
    ~ProgressReport();
    ProgressReport(const ProgressReport&) = delete;
    ProgressReport& operator=(const ProgressReport&) = delete;

    /// Rows done so far of the total, and the samples they took. Zero rows starts the clock.
    /// The last row (rows_done == rows_total) always prints: the bar's final state, or a last
    /// line if any line was printed before.
    void update(int rows_done, int rows_total, std::uint64_t samples);
    /// A message (a warning, a -dc column): printed on its own line, above the bar.
    void print_line(const std::string& line);

private:
    void draw_bar(const ProgressFigures& figures);
    void clear_bar();

    std::ostream& out_;
    Style style_;
    Clock clock_;
    std::string prefix_;
    std::mutex mutex_;  // rows and messages may come from different threads
    double start_ = 0.0;
    std::optional<double> last_print_;  ///< when the bar was drawn or a line printed
    ProgressFigures latest_;
    bool bar_shown_ = false;
    bool finished_ = false;
    bool printed_any_ = false;
};

}  // namespace rt
