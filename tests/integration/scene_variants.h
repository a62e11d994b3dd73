// The shipped gallery scene rewritten in the other dialects of the manual (2.2-2.5): with the
// smooth-shade field (-Po/-Pt), with marks and a shape file (-M), with its attributes inline
// (-Df), without power fields (-Dp), both (-Of), or with three indices of refraction (-R). The
// rewrites are plain text edits, written here so that no reader of rt is used to make them.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rt::test {

/// The named variants, each a folder with a copy of scenes/ in which some files are rewritten:
/// - "smooth": the smooth-shade field, 1 for the sphere, the red cube and the glass pane before
///   the yellow light, 0 for every other surface;
/// - "flat-field": the smooth-shade field, 0 for every surface;
/// - "marked": a shape file with one sphere; the sphere's polygons marked 2 (sphere, shape 0),
///   every other polygon marked 0;
/// - "marked-plain": the same files, every polygon marked 0;
/// - "inline": the attribute block in place of the Attributes file's name (-Df);
/// - "no-power": the attributes without pow and tpow (-Dp); "power-two": with both set to 2.0;
/// - "old-format": both of "inline" and "no-power" (-Of);
/// - "rgb-equal": each index of refraction written three times (-R);
/// - "rgb-spread": the same, but the glass gets 1.3 1.5 1.7.
/// Writes the variant into `folder` (created) and returns the path of its gallery.scn.
std::filesystem::path write_gallery_variant(std::string_view variant,
                                            const std::filesystem::path& folder);

// The text edits, exposed for their own tests.

/// The words of a line.
std::vector<std::string> words(const std::string& line);

/// Applies `edit` to every attribute line of an Attributes file (each `$` line after the count).
std::string edit_attributes(const std::string& text,
                            std::string (*edit)(const std::vector<std::string>& fields));

/// A filetype-0 optical surface file with `mark shape` after each polygon's attribute offset.
std::string with_marks(const std::string& surface_file, int mark, int shape);

}  // namespace rt::test
