#include "rt/app/progress_report.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace rt {

namespace {

constexpr int kBarWidth = 20;
// Back to the start of the line, and erase it: the bar is redrawn over itself.
constexpr const char* kReturnAndErase = "\r\033[K";

std::string time_left_text(const ProgressFigures& f) {
    const std::optional<double> left = f.seconds_left();
    return left ? format_duration(*left) + " left" : "?:?? left";
}

}  // namespace

double ProgressFigures::fraction() const {
    return rows_total > 0 ? std::clamp(static_cast<double>(rows_done) / rows_total, 0.0, 1.0) : 0.0;
}

double ProgressFigures::samples_per_second() const {
    return elapsed_seconds > 0.0 ? static_cast<double>(samples) / elapsed_seconds : 0.0;
}

std::optional<double> ProgressFigures::seconds_left() const {
    if (rows_done <= 0 || rows_total <= 0) {
        return std::nullopt;
    }
    return elapsed_seconds * static_cast<double>(std::max(rows_total - rows_done, 0)) / rows_done;
}

std::string format_duration(double seconds) {
    const auto whole = static_cast<long long>(std::llround(std::max(seconds, 0.0)));
    const long long hours = whole / 3600;
    const long long minutes = whole / 60 % 60;
    const long long secs = whole % 60;
    if (hours > 0) {
        return fmt::format("{}:{:02}:{:02}", hours, minutes, secs);
    }
    return fmt::format("{}:{:02}", minutes, secs);
}

std::string format_rate(double per_second) {
    const double r = std::max(per_second, 0.0);
    if (r < 999.5) {
        return fmt::format("{:.0f}", r);
    }
    const bool millions = r >= 999'500.0;
    const double scaled = millions ? r / 1e6 : r / 1e3;
    const char unit = millions ? 'M' : 'k';
    const int decimals = scaled < 9.995 ? 2 : (scaled < 99.95 ? 1 : 0);
    return fmt::format("{:.{}f}{}", scaled, decimals, unit);
}

std::string progress_bar_text(const ProgressFigures& f) {
    const int filled = static_cast<int>(std::floor(f.fraction() * kBarWidth));
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(kBarWidth - filled), '.');
    return fmt::format("[{}] {:>{}}/{} lines  {} samples/s  {} elapsed  {}", bar, f.rows_done,
                       fmt::formatted_size("{}", f.rows_total), f.rows_total,
                       format_rate(f.samples_per_second()), format_duration(f.elapsed_seconds),
                       time_left_text(f));
}

std::string progress_line_text(const ProgressFigures& f) {
    return fmt::format("{} of {} lines ({:.0f} %), {} samples/s, {} elapsed, {}", f.rows_done,
                       f.rows_total, std::floor(100.0 * f.fraction()),
                       format_rate(f.samples_per_second()), format_duration(f.elapsed_seconds),
                       time_left_text(f));
}

ProgressReport::ProgressReport(std::ostream& out, Style style, Clock clock, std::string prefix)
    : out_(out), style_(style), clock_(std::move(clock)), prefix_(std::move(prefix)) {}

ProgressReport::~ProgressReport() {
    if (bar_shown_) {
        out_ << '\n' << std::flush;
    }
}

void ProgressReport::update(int rows_done, int rows_total, std::uint64_t samples) {
    std::lock_guard lock(mutex_);
    const double now = clock_();
    if (rows_done == 0) {
        start_ = now;
        last_print_.reset();
        finished_ = false;
    }
    latest_ = {rows_done, rows_total, samples, now - start_};
    const bool last = rows_done >= rows_total;
    if (finished_) {
        return;
    }
    if (style_ == Style::Bar) {
        if (last || !last_print_ || now - *last_print_ >= kBarInterval) {
            draw_bar(latest_);
            last_print_ = now;
        }
        if (last) {
            out_ << '\n' << std::flush;
            bar_shown_ = false;
            finished_ = true;
        }
        return;
    }
    // Lines: the first after an interval, not at the start, so that short renders stay quiet.
    const double since = now - last_print_.value_or(start_);
    if ((last && printed_any_) || (!last && since >= kLineInterval)) {
        out_ << prefix_ << progress_line_text(latest_) << '\n' << std::flush;
        last_print_ = now;
        printed_any_ = true;
    }
    finished_ = last;
}

void ProgressReport::print_line(const std::string& line) {
    std::lock_guard lock(mutex_);
    clear_bar();
    out_ << line << '\n';
    // The bar comes back under the message, unless it was drawn a moment ago: a flood of
    // messages (-dc prints one a pixel) must not become a flood of bars.
    if (style_ == Style::Bar && last_print_ && !finished_) {
        const double now = clock_();
        if (now - *last_print_ >= kBarInterval) {
            latest_.elapsed_seconds = now - start_;
            draw_bar(latest_);
            last_print_ = now;
        }
    }
    out_ << std::flush;
}

void ProgressReport::draw_bar(const ProgressFigures& figures) {
    out_ << kReturnAndErase << prefix_ << progress_bar_text(figures) << std::flush;
    bar_shown_ = true;
}

void ProgressReport::clear_bar() {
    if (bar_shown_) {
        out_ << kReturnAndErase;
        bar_shown_ = false;
    }
}

}  // namespace rt
