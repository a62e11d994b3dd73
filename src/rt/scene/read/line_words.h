// The words of a line, for the model checks' walks over millions of lines.
#pragma once

#include <string_view>
#include <vector>

namespace rt {

/// Replaces `words` with the blank-separated words of `text`, as views into it.
void split_words(std::string_view text, std::vector<std::string_view>& words);

}  // namespace rt
