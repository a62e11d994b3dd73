// rt --resume NAME.gro: continues an interrupted render with what its header records (the scene
// and switches as command-line words, the seed, a digest of the input files), refusing whenever
// the result could differ from the uninterrupted render.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rt/app/options.h"
#include "rt/image/film.h"

namespace rt {

/// The render arguments as one header value: their words separated by spaces, a space inside a
/// word written "\s" and a backslash "\\".
std::string encode_arguments(const std::vector<std::vector<std::string>>& arguments);
/// The words of encode_arguments' text, as a command line.
std::vector<std::string> decode_arguments(std::string_view text);

struct ResumePlan {
    /// The recorded render's options, with the resume command's --output, --threads, --quiet and
    /// --no-window.
    Options options;
    Film done;  ///< the interrupted picture
};

/// Reads given.resume and checks it can be resumed: it records its arguments, is unfinished, was
/// written by this version, and the scene and switches given (if any) are the recorded ones.
/// Throws UsageError saying why not (InputError, IoError for a file that cannot be read).
ResumePlan plan_resume(const Options& given);

/// Throws UsageError unless the render's inputs and window are those of the interrupted one.
void check_resumable(const Film& done, const std::string& inputs, int view_width, int view_height,
                     const PixelRect& window);

}  // namespace rt
