#include "rt/image/film_reference.h"

#include <algorithm>
#include <cmath>

#include "rt/core/error.h"

namespace rt {

namespace {

constexpr double kDisplayLevels = 255.0;

void check_same_window(const Film& a, const Film& b) {
    if (!(a.window() == b.window()) || a.data().size() != b.data().size()) {
        throw Error("a film of another window cannot be compared with this reference");
    }
}

}  // namespace

void FilmReference::add(const Film& film) {
    if (count_ == 0) {
        shape_ = film;
        mean_.assign(film.data().size(), 0.0);
        square_.assign(film.data().size(), 0.0);
    }
    check_same_window(shape_, film);
    ++count_;
    const std::vector<float>& data = film.data();
    for (std::size_t i = 0; i < data.size(); ++i) {
        const double delta = data[i] - mean_[i];
        mean_[i] += delta / count_;
        square_[i] += delta * (data[i] - mean_[i]);
    }
}

double FilmReference::noise_variance() const {
    if (count_ < 2) {
        throw Error("a reference needs two renders or more to know its own noise");
    }
    double sum = 0.0;
    for (const double s : square_) {
        sum += s;
    }
    // Each channel's sample variance s / (n - 1), divided by n for the variance of the mean.
    const double n = count_;
    return sum / (n - 1.0) / n / static_cast<double>(square_.size()) * kDisplayLevels *
           kDisplayLevels;
}

double FilmReference::mean_squared_error(const Film& film) const {
    check_same_window(shape_, film);
    const std::vector<float>& data = film.data();
    double sum = 0.0;
    for (std::size_t i = 0; i < data.size(); ++i) {
        const double d = data[i] - mean_[i];
        sum += d * d;
    }
    return sum / static_cast<double>(data.size()) * kDisplayLevels * kDisplayLevels -
           noise_variance();
}

double FilmReference::rms_error(const Film& film) const {
    return std::sqrt(std::max(0.0, mean_squared_error(film)));
}

Film FilmReference::mean() const {
    Film out = shape_;
    std::transform(mean_.begin(), mean_.end(), out.data().begin(),
                   [](double v) { return static_cast<float>(v); });
    return out;
}

}  // namespace rt
