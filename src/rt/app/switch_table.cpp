// The rows of the switch table, in the order of the manual's Appendix. Summaries are the manual's
// own one-line descriptions; details shorten the Appendix's explanation. Turning a switch on in a
// later release is one word: Status::NotYet becomes Status::Implemented.
#include "rt/app/switch_table.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/text.h"

namespace rt {

namespace {

using A = const SwitchArgument&;
using enum ArgForm;
using enum Topic;
using enum Status;

constexpr Range kPositive{0.0, 0.0, true, false, false};
constexpr Range kNonNegative{0.0, 0.0, false, false, false};
constexpr Range kProbability{0.0, 1.0, true, true, true};
constexpr Range kWeight{0.0, 1.0, false, false, true};
constexpr Range kAngle{0.0, std::numbers::pi, true, false, true};
constexpr Range kMicrofacetSlope{kLeastMicrofacetSlope, 0.0, false, false, false};

// --accel NAME: its row has no range, so the name is checked here, once.
void set_accel_kind(Options& o, A a) {
    const std::optional<AccelKind> kind = accel_kind_from_name(a.text);
    if (!kind) {
        throw UsageError("--accel: expected brute, octree, seads, bvh or embree, found " +
                         quote_token(a.text));
    }
    o.accel.method.kind = *kind;
}

constexpr Range whole(int low, int high) {
    return {static_cast<double>(low), static_cast<double>(high), false, false, true};
}

// -S: the law and its slope m (1 for the Phong laws, which do not use it); the Gaussian normaliser
// is computed here, once. The highlight colour (-C) is kept.
void set_specular_law(Options& o, SpecularLaw law, double slope_m) {
    o.shading.specular = make_specular_settings(law, slope_m, o.shading.specular.tint);
}

// Each row names only the fields it needs; the rest keep SwitchSpec's defaults on purpose, which
// GCC 12 would otherwise flag row by row.
// A table reads best one compact row per switch.
// clang-format off
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
constexpr auto kSwitches = std::to_array<SwitchSpec>({
    {.spelling = "-n", .apply = [](Options& o, A) { o.no_gro = true; }, .summary = "No output file",
     .details = "Disables the production of a .gro file; --output files are still written.",
     .section = "App.", .example = "-n"},
    {.spelling = "-w", .apply = [](Options& o, A) { o.wireframe_only = true; },
     .summary = "Wireframe only, no raytracing",
     .details = "Draws every polygon's edges (white) and the header's normallength normals "
                "(green) through the renderer's camera into the picture (the .gro and --output "
                "files), and traces no ray (docs/wireframe.md).", .section = "App.",
     .example = "-w"},
    {.spelling = "-m", .form = Number, .first = {"the multiplier", kPositive},
     .apply = [](Options& o, A a) { o.display.multiplier = a.first; },
     .summary = "Multiplies screen display values by 2.",
     .details = "Compensates a picture that is too dark or too bright; an RGB value over 255 "
                "scales the pixel down proportionally unless -c is given.", .section = "App.",
     .example = "-m2.0"},
    {.spelling = "-tv", .form = Integer, .topic = SpatialEncoding,
     .first = {"N", whole(1, 1000000)},
     .apply = [](Options& o, A a) { o.accel.method.terminate_after_voxels = static_cast<int>(a.integer); },
     .summary = "Terminate rays after N fruitless voxel hits",
     .details = "Ends a ray as a miss after N voxels without any hit (a near hit waiting for its "
                "voxel keeps it going): faster, and a different picture by design. Shadow "
                "feelers too: one cut short lets its light through.",
     .section = "3.1", .example = "-tv8"},
    {.spelling = "-c", .apply = [](Options& o, A) { o.display.clip = false; },
     .summary = "Toggle intensity clipping. Currently on by default.",
     .details = "Turns clipping off: an intensity over 255 is displayed anyway, which can give "
                "very strange colors.", .section = "App.", .example = "-c"},
    {.spelling = "-od", .form = Integer, .topic = SpatialEncoding,
     .first = {"the depth", whole(0, 20)},
     .apply = [](Options& o, A a) { o.accel.method.octree.depth = static_cast<int>(a.integer); },
     .summary = "Specify octree depth (overrides scene file)",
     .details = "For studying the effects of different octree depths.", .section = "App.",
     .example = "-od5", .setting = "octree depth"},
    {.spelling = "-oo", .topic = SpatialEncoding,
     .apply = [](Options& o, A) { o.draw_octree = true; },
     .summary = "Draw (output) octree boxes on the wireframe",
     .details = "To see what the octree building machinery is doing: with -w, the boxes of "
                "the octree's leaves are drawn too (blue). It is the octree --accel octree or the "
                "header builds, built for the drawing whatever the method. Without -w the "
                "picture is ray traced as usual.", .section = "App.",
     .example = "-oo"},
    {.spelling = "-ol", .form = Integer, .topic = SpatialEncoding,
     .first = {"the power of 2", whole(1, 30)},
     .apply = [](Options& o, A a) { o.accel.method.octree.octlist_power = static_cast<int>(a.integer); },
     .summary = "Specify the length of the octlist, as a power of 2",
     .details = "The octree may use at most 2^n nodes (default 2^24, 8 bytes each); a tree that "
                "needs more stops with an error naming -ol.",
     .section = "App.", .example = "-ol16", .setting = "octree node limit"},
    {.spelling = "-on", .topic = SpatialEncoding,
     .apply = [](Options& o, A) { o.accel.method.accept_near_hits = true; },
     .summary = "Don't verify near hits (just accept them)",
     .details = "Accepts a hit lying beyond the voxel being searched at once. By default it waits "
                "for its voxel, which gives exactly brute force's answer; -on can miss a nearer "
                "polygon in a later voxel.", .section = "3.1",
     .example = "-on"},
    {.spelling = "-of", .topic = SpatialEncoding, .apply = [](Options& o, A) { o.accel.method.no_fudge = true; },
     .summary = "Don't fudge (ddda is precise enough)",
     .details = "No fudge: polygons are filed in voxels without growing them (by 2^-24 of "
                "the world) and hits are accepted without the rounding slack; answers may then "
                "differ from brute force at voxel faces.", .section = "App.",
     .example = "-of"},
    {.spelling = "-op", .topic = SpatialEncoding,
     .apply = [](Options& o, A) { o.accel.method.octree.level_order = true; },
     .summary = "Use new fillplane routines.",
     .details = "Fills the octree one level at a time (breadth first) instead of depth first; the "
                "tree is the same.",
     .section = "App.", .example = "-op"},
    {.spelling = "-ss", .form = Integer, .topic = SpatialEncoding,
     .first = {"the power of 2", whole(0, 30)},
     .apply = [](Options& o, A a) { o.accel.method.octree.seed_size_power = static_cast<int>(a.integer); },
     .summary = "Specify the seeds size as a power of 2",
     .details = "The octree's node pool starts at 2^n nodes (default 2^12) and doubles as "
                "needed up to the -ol limit; the tree is the same.", .section = "App.",
     .example = "-ss10", .setting = "octree seed size"},
    {.spelling = "-p", .topic = SpatialEncoding, .apply = [](Options& o, A) { o.profile = true; },
     .summary = "Profile ddda operation.",
     .details = "Prints, at the end of the run on standard output, per kind of ray (eye, reflected, "
                "refracted, diffuse, shadow feeler, probe, random): rays traced, voxels stepped, "
                "nodes visited, polygons tested, hits, near hits, culled exits and rays answered "
                "from the few polygons a leaving ray may meet or an eye ray's tile of pixels "
                "may see (guarded); the intersection "
                "structure's memory; the time of each phase; and the rays of every kind traced "
                "per second of the trace's wall time.",
     .section = "App.", .example = "-p"},
    {.spelling = "-r", .topic = SpatialEncoding,
     .apply = [](Options& o, A) { o.random_rays = true; }, .summary = "Fire random rays.",
     .details = "Fires as many random rays as the window has pixels (origins in the doubled bounding "
                "box, uniform directions) and writes no picture. Useful with -p.", .section = "App.",
     .example = "-r"},
    {.spelling = "-Sp", .group = Exclusive::SpecularModel, .topic = Specular,
     .apply = [](Options& o, A) { set_specular_law(o, SpecularLaw::Phong, 1.0); },
     .summary = "Phong",
     .details = "The default specular reflection model.", .section = "App.", .example = "-Sp"},
    {.spelling = "-Sg", .group = Exclusive::SpecularModel, .topic = Specular,
     .apply = [](Options& o, A) { set_specular_law(o, SpecularLaw::PhongGeometric, 1.0); },
     .summary = "Phong with geometric attenuation factor", .section = "App.", .example = "-Sg"},
    {.spelling = "-Stg", .form = Number, .group = Exclusive::SpecularModel, .topic = Specular,
     .first = {"m", kMicrofacetSlope},
     .apply = [](Options& o, A a) {
         set_specular_law(o, SpecularLaw::TorranceSparrowGaussian, a.first);
     },
     .summary = "Torrance-Sparrow with Gaussian dist.; the # is m",
     .details = "m is the root mean square slope of the microfacets.", .section = "App.",
     .example = "-Stg1.0", .setting = "microfacet slope m"},
    {.spelling = "-Stb", .form = Number, .group = Exclusive::SpecularModel, .topic = Specular,
     .first = {"m", kMicrofacetSlope},
     .apply = [](Options& o, A a) {
         set_specular_law(o, SpecularLaw::TorranceSparrowBeckmann, a.first);
     },
     .summary = "Torrance-Sparrow with Beckmann dist.; the # is m",
     .details = "m is the root mean square slope of the microfacets.", .section = "App.",
     .example = "-Stb1.0", .setting = "microfacet slope m"},
    {.spelling = "-R", .topic = FileFormat,
     .apply = [](Options& o, A) { o.dialect.rgb_refraction = true; },
     .summary = "Each attribute in .scn file has 3 (RGB) indices of refraction",
     .details = "Then ALL attributes must have three indices of refraction.", .section = "2.3",
     .example = "-R"},
    {.spelling = "-Wr", .group = Exclusive::WarnLight, .topic = Lights,
     .apply = [](Options& o, A) { o.shading.warn = {WarnMode::Rogers, 0.0, 0.0}; },
     .summary = "Warn lights: Rogers",
     .details = "With shadow feeling, the feeler's intensity is attenuated by pow(cos(x), N), x "
                "the angle to the emissive polygon's normal.", .section = "App.", .example = "-Wr"},
    {.spelling = "-Wc", .form = Number, .group = Exclusive::WarnLight,
     .topic = Lights, .first = {"the angle", kAngle},
     .apply = [](Options& o, A a) { o.shading.warn = {WarnMode::Conical, a.first, 0.0}; },
     .summary = "Warn lights: conical; # is angle in radians",
     .details = "Same as -Wr except that no light is obtained beyond the angle.", .section = "App.",
     .example = "-Wc 0.7"},
    {.spelling = "-Wt", .form = Number, .group = Exclusive::WarnLight, .topic = Lights,
     .first = {"the distance", kPositive},
     .apply = [](Options& o, A a) { o.shading.warn = {WarnMode::Thibadeau, 0.0, a.first}; },
     .summary = "Warn lights: Thibadeau; # is dist. from poly",
     .details = "The point source is displaced behind the emissive polygon; light arrives only "
                "through the polygon.", .section = "App.", .example = "-Wt1.0"},
    {.spelling = "-A", .form = Pair, .topic = Lights, .first = {"the distance", kPositive},
     .second = {"the constant", kPositive},
     .apply = [](Options& o, A a) {
         o.shading.attenuation_distance = a.first;
         o.shading.attenuation_constant = a.second;
     },
     .summary = "Attenuation effect: intensity divided by dist/40.0 + 1.0",
     .details = "NOT the inverse-square law. By default attenuation is on, with 200.0 and 1.0.",
     .section = "App.", .example = "-A40.0,1.0"},
    {.spelling = "-T", .topic = Lights,
     .apply = [](Options& o, A) { o.shading.far_side_feelers = true; },
     .summary = "Specular refraction",
     .details = "Also considers shadow feelers on the far side of a polygon that is not opaque.",
     .section = "App.", .example = "-T"},
    {.spelling = "-Co", .group = Exclusive::HighlightColor, .topic = Highlights,
     .apply = [](Options& o, A) { o.shading.specular.tint = HighlightTint::ObjectColor; },
     .summary = "Object color attenuates light color",
     .details = "Specular highlights are filtered through the color of the polygon.",
     .section = "App.", .example = "-Co"},
    {.spelling = "-Ci", .group = Exclusive::HighlightColor, .topic = Highlights,
     .apply = [](Options& o, A) { o.shading.specular.tint = HighlightTint::LightColor; },
     .summary = "Light color only",
     .details = "Specular highlights are the color of the incident light.", .section = "App.",
     .example = "-Ci"},
    {.spelling = "-Cf", .group = Exclusive::HighlightColor, .topic = Highlights,
     .apply = [](Options& o, A) { o.shading.specular.tint = HighlightTint::Fresnel; },
     .summary = "Fresnel function applied to RGB components separately",
     .details = "Specular highlights vary with the wavelength of the incident light.",
     .section = "App.", .example = "-Cf"},
    {.spelling = "-Dx", .topic = Disable, .apply = [](Options& o, A) { o.shading.sampling.adaptive = false; },
     .summary = "disable adaptive supersampling",
     .details = "Takes the maximum number of samples per pixel (the sample resolution squared).",
     .section = "App.", .example = "-Dx"},
    {.spelling = "-De", .topic = Disable,
     .apply = [](Options& o, A) { o.accel.exit_culling = false; },
     .summary = "disable exit ray culling",
     .details = "Exit-ray culling ends at once the rays that cannot hit anything: a table of world "
                "regions and direction bins, built before rendering, says where nothing lies ahead, "
                "and for eye rays a bitmap of the pixels the scene covers "
                "(docs/exit-culling-and-zbuffer.md). It never changes the picture. -De turns it "
                "off, e.g. when the table takes too long to build. Without -De it is left out of "
                "a scene with more polygons than the render has rays from the eye, whose table "
                "could not pay for itself; -p says so.", .section = "App.",
     .example = "-De"},
    {.spelling = "-Dd", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.sampling.distribute = false; },
     .summary = "disable Distributing",
     .details = "Only one transmitted and one reflected ray per intersection: quick but "
                "unrealistic pictures.", .section = "App.", .example = "-Dd"},
    {.spelling = "-Dt", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.feelers_stop_at_transparent = true; },
     .summary = "prevent shadow feelers from penetrating Transparent polys",
     .details = "The shadow feeler stops dead at the first polygon it hits.", .section = "App.",
     .example = "-Dt"},
    {.spelling = "-Da", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.attenuate_rays = false; },
     .summary = "disable Attenuation with distance (excluding LightLock)",
     .details = "Light rays other than shadow feelers do not attenuate with distance.",
     .section = "App.", .example = "-Da"},
    {.spelling = "-Dl", .alias = "-DI", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.attenuate_feelers = false; },
     .summary = "disable attenuation with distance of Lights",
     .details = "Shadow feelers do not attenuate with distance. The manual prints it -DI, which "
                "is accepted too.", .section = "App.", .example = "-Dl"},
    {.spelling = "-Ds", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.shadow_feelers = false; },
     .summary = "disable Shadow feeler", .details = "Eliminates shadow feeling.", .section = "App.",
     .example = "-Ds"},
    {.spelling = "-Dr", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.reflection = false; }, .summary = "disable Reflection",
     .details = "No reflected rays, even at a reflective polygon.", .section = "App.",
     .example = "-Dr"},
    {.spelling = "-Df", .topic = FileFormat,
     .apply = [](Options& o, A) { o.dialect.attributes_inline = true; },
     .summary = "read attributes from .scn and not separate File",
     .details = "The attribute list stands in the .scn in place of the Attributes file name.",
     .section = "2.2", .example = "-Df"},
    {.spelling = "-Dp", .topic = FileFormat,
     .apply = [](Options& o, A) { o.dialect.no_power_fields = true; },
     .summary = "Power fields not present in attribute description",
     .details = "pow and tpow are absent from EVERY attribute and taken as 2.0.", .section = "2.3",
     .example = "-Dp"},
    {.spelling = "-Db", .topic = Disable,
     .apply = [](Options& o, A) { o.shading.both_sides_emit = false; },
     .summary = "not Both sides of polygons are emissive",
     .details = "Only the outside surface of emissive polygons emits light.", .section = "App.",
     .example = "-Db"},
    {.spelling = "-Po", .group = Exclusive::PhongShading, .topic = FileFormat,
     .apply = [](Options& o, A) {
         o.dialect.smooth_shade_field = true;
         o.shading.smooth_shaded_opaque = true;
     },
     .summary = "Phong shaded objects are opaque",
     .details = "The .scn has the smooth-shading field; such objects are forced opaque (the "
                "preferred option).", .section = "2.2", .example = "-Po"},
    {.spelling = "-Pt", .group = Exclusive::PhongShading, .topic = FileFormat,
     .apply = [](Options& o, A) { o.dialect.smooth_shade_field = true; },
     .summary = "Phong shaded objects are transparent",
     .details = "The .scn has the smooth-shading field; opaqueness is not forced.",
     .section = "2.2", .example = "-Pt"},
    {.spelling = "-Ot", .topic = OldVersions,
     .apply = [](Options& o, A) { o.shading.correct_smoothing = false; },
     .summary = "Old intersection test",
     .details = "Smooth-shaded normals can face away from the ray, and reflected or refracted rays "
                "can then leave on the wrong side; by default both are corrected (the normal is "
                "turned back, the ray reflected about the geometric normal or sent straight on). "
                "-Ot disables the correction.",
     .section = "App.", .example = "-Ot"},
    {.spelling = "-Oi", .topic = OldVersions,
     .apply = [](Options& o, A) { o.early = EarlyVersion::OldIllumination; }, .summary = "Old illumination model",
     .details = "Simulates the earliest version of the raytracer: no attenuation with distance, "
                "shadow feelers that stop at any polygon, no distributed rays, and every point "
                "source of an emitter at the emitter's full power (see docs/rendering.md).",
     .section = "App.", .example = "-Oi"},
    {.spelling = "-Of", .topic = FileFormat,
     .apply = [](Options& o, A) {
         o.dialect.attributes_inline = true;
         o.dialect.no_power_fields = true;
     },
     .summary = "Old format", .details = "Same as -Df -Dp.", .section = "2.3", .example = "-Of"},
    {.spelling = "-O1", .topic = OldVersions, .apply = [](Options& o, A) { o.early = EarlyVersion::OldVersion; },
     .summary = "Behave like an early version of the CMU raytracer",
     .details = "Before certain bugs had been ironed out: -Oi, taking every sample of every pixel. "
                "It must be used alone, without other switches.", .section = "2.1", .example = "-O1"},
    {.spelling = "-K", .topic = Illumination,
     .apply = [](Options& o, A) { o.scale_weights = true; },
     .summary = "scale down ka, ks, etc. so that intensity need not be clipped",
     .details = "Looks at -Dr and -Ds. Produces correct but dark pictures.", .section = "App.",
     .example = "-K"},
    {.spelling = "-I", .topic = Illumination,
     .apply = [](Options& o, A) { o.shading.sampling.illuminate_distributed = true; },
     .summary = "apply illum. model to distrib. rays as well as shadow feelers",
     .details = "Gives the distributed rays the full illumination model treatment: highlights, and "
                "distribution of their own reflected and refracted rays (down to maxdist).",
     .section = "App.", .example = "-I"},
    {.spelling = "-L", .form = Integer, .first = {"the line", whole(0, 1000000)},
     .apply = [](Options& o, A a) { o.start_line = static_cast<int>(a.integer); },
     .summary = "draws only from line 250 up",
     .details = "Lines are drawn from the bottom up; this starts at line 250.", .section = "App.",
     .example = "-L250", .setting = "start line"},
    {.spelling = "-E", .form = Number, .topic = Illumination, .first = {"the angle", kAngle},
     .apply = [](Options& o, A a) { o.crease_angle = a.first; },
     .summary = "Sharp breaks in Phong-shaded objects if angle 1.5 radians",
     .details = "Smooth shading averages the normals of the polygons at a vertex only over those "
                "within the angle (radians) of the polygon's own normal, so sharper creases stay "
                "sharp.", .section = "App.", .example = "-E1.5"},
    {.spelling = "-F", .form = Pair, .topic = Lights, .first = {"distangle", kPositive},
     .second = {"distfac", kPositive},
     .apply = [](Options& o, A a) {
         o.shading.fuzzy = {a.first, static_cast<int>(std::ceil(a.second))};
     },
     .summary = "Fuzzy shadow feeler: 0.3 is distangle, 2.0 is distfac",
     .details = "Distributes the shadow feeler to produce fuzzy shadows: distfac feelers per light "
                "(rounded up), each turned at random by up to distangle radians from the light.", .section = "App.",
     .example = "-F0.3,2.0"},
    {.spelling = "-Xp", .form = Pair, .topic = AdaptiveSampling,
     .first = {"the probability", kProbability}, .second = {"the variance", kPositive},
     .apply = [](Options& o, A a) { o.shading.sampling.pixel_stop = {a.first, a.second}; },
     .summary = "Stop sampling pixels when prob that variance 0.05 is .1",
     .details = "Chi-square adaptive sampling of the n x n samples of a pixel: sampling stops once "
                "the chance that the variance of the pixel's mean exceeds var (in display levels "
                "squared) is below prob. The defaults are 0.2 and 0.2.",
     .section = "App.", .example = "-Xp0.1,0.05"},
    {.spelling = "-Xr", .form = Pair, .topic = AdaptiveSampling,
     .first = {"the probability", kProbability}, .second = {"the variance", kPositive},
     .apply = [](Options& o, A a) { o.shading.sampling.ray_stop = {a.first, a.second}; },
     .summary = "Ditto, except with distributed rays and not pixels",
     .details = "Chi-square adaptive sampling of the distributed rays at an intersection (at most "
                "n x n of them, n the sample resolution), with the same rule as -Xp.", .section = "App.",
     .example = "-Xr0.1,0.05"},
    {.spelling = "-M", .topic = FileFormat, .apply = [](Options& o, A) { o.dialect.marks = true; },
     .summary = "op surf files mark polys; Shape file name in .scn file",
     .details = "Used if and only if the .scn has a $@shapes line (not with Phigs or Chen's "
                "files).", .section = "2.4", .example = "-M"},
    {.spelling = "-V", .topic = FileFormat,
     .apply = [](Options& o, A) { o.dialect.textures = true; }, .summary = "texture mapping",
     .details = "Texture-mapped optical surfaces follow the entities in the .scn: a count, then "
                "per surface its attribute, polygon grid, texture map (sphere, cylinder, axis and "
                "colour per cell), scale, translation, rotation, rows and columns.",
     .section = "2.2", .example = "-V"},
    {.spelling = "-dc", .topic = Debugging, .apply = [](Options& o, A) { o.print_columns = true; },
     .summary = "print column numbers",
     .details = "Prints the column number of the pixel on each sample: 'line Y column X' on "
                "standard error as each pixel's sampling starts, rows from the bottom up.",
     .section = "App.",
     .example = "-dc"},
    {.spelling = "-ds", .topic = Debugging, .apply = [](Options& o, A) { o.accel.strike_check = true; },
     .summary = "(strike) debug ddda by comparing actual results (slow)",
     .details = "Traces every ray and shadow feeler again by brute force and counts the answers "
                "that differ; the count is printed at the end.",
     .section = "App.", .example = "-ds"},
    {.spelling = "-dsp", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.strike_print = true; },
     .summary = "(strike print) print hits different only in poly, but not oct",
     .details = "Prints each difference the strike check finds (implies -ds).", .section = "App.",
     .example = "-dsp"},
    {.spelling = "-dso", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.strike_voxels = true; },
     .summary = "(strike oct) print octs looked in",
     .details = "With each difference, prints the voxels (octs) the walk looked in (implies "
                "-ds).", .section = "App.", .example = "-dso"},
    {.spelling = "-dl", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.log_intersections = true; }, .summary = "print intersections",
     .details = "Prints every nearest-hit query and its answer, whatever the method (the original "
                "printed brute force's only).", .section = "App.",
     .example = "-dl"},
    {.spelling = "-doo", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.octree_listing = "octree.lst"; },
     .summary = "Output the octree to octree.lst",
     .details = "Writes octree.lst in the current folder: every node, depth first, with the "
                "polygon ids of each leaf.", .section = "App.", .example = "-doo"},
    {.spelling = "-doi", .topic = Debugging,
     .apply = [](Options& o, A) { o.debug_octree_interactive = true; },
     .summary = "Debug octree interactively",
     .details = "Did not work in the original. Builds the octree and reads commands on standard "
                "input (help, node, child N, up, root, list, find X Y Z, ray OX OY OZ DX DY DZ, "
                "pixel X Y, quit), answering on standard output; renders no picture.",
     .section = "App.", .example = "-doi"},
    {.spelling = "-dof", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.trace_fill = true; }, .summary = "Debug octree fillplane",
     .details = "Traces the -op fill-plane build of the octree level by level on standard error: "
                "nodes, polygon references, leaves and splits of each level. Only with -op.", .section = "App.", .example = "-dof"},
    {.spelling = "-df", .topic = Debugging, .apply = [](Options& o, A) { o.trace_parsing = true; },
     .summary = "(file) debug file parsing",
     .details = "Traces the parsing of every file read, on stderr.", .section = "App.",
     .example = "-df"},
    {.spelling = "-dd", .topic = Debugging, .apply = [](Options& o, A) { o.debug_color = true; },
     .summary = "debug color info",
     .details = "Prints the color map (the display mapping of -m and -c) and every pixel's display "
                "value and intensity, row by row from the bottom, on standard error.", .section = "App.",
     .example = "-dd"},
    {.spelling = "-dx", .topic = Debugging,
     .apply = [](Options& o, A) { o.debug_chi_square = true; }, .summary = "Debug chi-square stuff",
     .details = "Prints, for each pixel, the samples taken, the intersections that distributed rays "
                "and the distributed rays sent.", .section = "App.", .example = "-dx"},
    {.spelling = "-de", .topic = Debugging,
     .apply = [](Options& o, A) { o.accel.check_exit_culling = true; },
     .summary = "Debug exit ray culling",
     .details = "Traces every culled ray with the intersection method as well and counts those that "
                "hit something, and every ray answered from the few polygons a leaving ray may "
                "meet and counts those the method answers otherwise (there should be none of "
                "either); prints the statistics at the end of the run, as -p does.",
     .section = "App.",
     .example = "-de"},
    {.spelling = "--output", .form = Text, .topic = Program, .first = {"FILE", {}},
     .repeatable = true, .apply = [](Options& o, A a) { o.outputs.push_back(a.text); },
     .summary = "Also write the picture to FILE (.gro, .exr, .png or .ppm)",
     .details = "Repeatable; the format follows the extension. .gro and .exr keep the linear "
                "intensities (32-bit floats); .png and .ppm the 8-bit picture.", .section = "new",
     .example = "--output twocubes.png", .recorded = false},
    {.spelling = "--resume", .form = Text, .topic = Program, .first = {"FILE.gro", {}},
     .apply = [](Options& o, A a) { o.resume = a.text; },
     .summary = "Continue the interrupted render FILE.gro",
     .details = "Renders the rows FILE.gro lacks with the scene, switches and seed its header "
                "records, and writes it back complete: the same picture, bit for bit, as a "
                "render that was never interrupted. Refused if the scene's files have changed or "
                "if a scene or switches are given that differ from the recorded ones (none may be "
                "given: the recorded ones are used). Run it in the folder the render started in.",
     .section = "new", .example = "--resume twocubes.gro", .recorded = false},
    {.spelling = "--model", .form = Text, .topic = Program, .first = {"FILE", {}},
     .apply = [](Options& o, A a) { o.model = a.text; },
     .summary = "Render the model FILE (.obj, .ply, .stl, .gltf, .off, ...) without a scene",
     .details = "In place of the SCENE: the model, scaled to 10 units, stands on a checkerboard "
                "under a square light, seen from in front (+z) and above. Every other "
                "switch applies; -Po or -Pt smooth-shade the model. The picture is FILE's stem "
                "with .gro.", .section = "new", .example = "--model scenes/models/bunny.ply"},
    {.spelling = "--help", .topic = Program, .apply = [](Options& o, A) { o.show_help = true; },
     .summary = "Print this help and stop", .section = "new", .example = "--help", .recorded = false},
    {.spelling = "--version", .topic = Program,
     .apply = [](Options& o, A) { o.show_version = true; }, .summary = "Print the version and stop",
     .section = "new", .example = "--version", .recorded = false},
    {.spelling = "--seed", .form = Integer, .topic = Program, .first = {"N", kNonNegative},
     .apply = [](Options& o, A a) { o.shading.sampling.seed = static_cast<std::uint64_t>(a.integer); },
     .summary = "Seed of the random numbers (the same seed, the same picture)", .section = "new",
     .example = "--seed 7"},
    {.spelling = "--cutoff", .form = Number, .topic = Illumination, .first = {"W", kWeight},
     .apply = [](Options& o, A a) { o.shading.weight_cutoff = a.first; },
     .summary = "Trace no secondary ray whose weight is below W (0: trace all)",
     .details = "A ray's weight is the product of the reflection and transmission coefficients "
                "on its path from the eye (for a colour, its largest channel); a branch lighter "
                "than W is left out, as adaptive tree-depth control does (Hall and Greenberg). "
                "Tames ray trees that double at every level; off by default, so pictures are "
                "the manual's (docs/rendering.md).", .section = "new",
     .example = "--cutoff 0.01"},
    {.spelling = "--threads", .form = Integer, .topic = Program,
     .first = {"N", whole(0, 1024)},
     .apply = [](Options& o, A a) { o.threads = static_cast<int>(a.integer); },
     .summary = "Build the intersection method and render on N threads (0: every core)", .section = "new", .example = "--threads 2", .recorded = false},
    {.spelling = "--tile", .form = Text, .topic = Program, .first = {"I/N", {}},
     .apply = [](Options& o, A a) { o.tile = parse_picture_part(a.text); },
     .summary = "Render only part I of N into a part file, for merge",
     .details = "Cuts the window into N bands of rows from the top and renders band I into "
                "NAME.part-I-of-N.gro; the program merge joins the N part files into the .gro "
                "and images a single run writes, pixel for pixel (docs/distributed.md). Not "
                "with -n or --output.", .section = "new", .example = "--tile 2/3", .recorded = false},
    {.spelling = "--accel", .form = Text, .topic = SpatialEncoding,
     .first = {"NAME", {}}, .apply = set_accel_kind,
     .summary = "Intersection method: brute, octree, seads, bvh or embree",
     .details = "Overrides the third and fourth numbers of the scene header. When the header "
                "names another method, octree and seads size themselves for the scene: a depth "
                "measured on the scene (-od overrides it) and 0.7 cbrt(polygons) voxels a side. "
                "embree (a comparison only, not exact) needs a build with Embree 3.",
     .section = "new", .example = "--accel bvh"},
    {.spelling = "--zbuffer", .topic = SpatialEncoding,
     .apply = [](Options& o, A) { o.accel.zbuffer_first_hits = true; },
     .summary = "Find the eye rays' first hits with a z-buffer",
     .details = "Rasterises the polygons into an item buffer and takes each eye ray's first "
                "polygon from it; the rest of the ray tree uses the intersection method.",
     .section = "3.1", .example = "--zbuffer"},
    {.spelling = "--quiet", .topic = Program, .apply = [](Options& o, A) { o.quiet = true; },
     .summary = "No progress and no notes; warnings and errors still show",
     .details = "Without it, progress goes to standard error: a bar on a terminal, a line every "
                "5 seconds elsewhere.", .section = "new",
     .example = "--quiet", .recorded = false},
    {.spelling = "--no-window", .topic = Program,
     .apply = [](Options& o, A) { o.no_window = true; },
     .summary = "Render without a window, even on a display",
     .details = "On a display rt opens a window of the picture's size, draws the wireframe in "
                "it, fills the lines in as they finish and at the end waits for Enter (or for "
                "the window to close; at once when standard input is not a terminal). Without "
                "a display it renders without one (docs/window.md).",
     .section = "1.2.2", .example = "--no-window", .recorded = false},
    {.spelling = "--max-memory", .form = Number, .topic = Program, .first = {"GIB", kPositive},
     .apply = [](Options& o, A a) { o.max_memory_gib = a.first; },
     .summary = "Refuse a render that needs more than GIB gibibytes",
     .details = "Before allocating the picture, rt estimates the memory the render needs (the "
                "film, the window, the outputs' buffers, the intersection method) and refuses it "
                "if it needs more than the memory available (MemAvailable, or the cgroup's or "
                "ulimit's limit). This sets the limit instead.",
     .section = "new", .example = "--max-memory 2", .recorded = false},
});
#pragma GCC diagnostic pop
// clang-format on

std::string format_bound(double value) {
    if (value == std::numbers::pi) {
        return "pi";
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
    return std::string(text, result.ptr);
}

}  // namespace

bool Range::contains(double value) const {
    const bool above_low = low_open ? value > low : value >= low;
    const bool below_high = !bounded_above || (high_open ? value < high : value <= high);
    return above_low && below_high;
}

std::string Range::describe() const {
    if (!bounded_above) {
        return (low_open ? "> " : ">= ") + format_bound(low);
    }
    if (!low_open && !high_open) {
        return "from " + format_bound(low) + " to " + format_bound(high);
    }
    return std::string("in ") + (low_open ? "(" : "[") + format_bound(low) + ", " +
           format_bound(high) + (high_open ? ")" : "]");
}

std::span<const SwitchSpec> switch_table() {
    return kSwitches;
}

std::string name_the_switches(const std::string& message) {
    // Settings a program can only set in the scene file.
    constexpr std::array<std::pair<std::string_view, std::string_view>, 1> kInScene{
        {{"SEADS voxels a side", "the scene header's third number, or --accel seads"}}};
    std::string text = message;
    const auto name = [&](std::string_view setting, const std::string& by) {
        const std::size_t at = text.find(setting);
        if (at != std::string::npos) {
            text.insert(at + setting.size(), " (" + by + ")");
        }
    };
    std::vector<std::string_view> done;
    for (const SwitchSpec& spec : kSwitches) {
        if (spec.setting.empty() ||
            std::find(done.begin(), done.end(), spec.setting) != done.end()) {
            continue;
        }
        done.push_back(spec.setting);
        std::string by;
        for (const SwitchSpec& other : kSwitches) {
            if (other.setting == spec.setting) {
                by += (by.empty() ? "" : " or ") + std::string(other.spelling);
            }
        }
        name(spec.setting, by);
    }
    for (const auto& [setting, by] : kInScene) {
        name(setting, std::string(by));
    }
    return text;
}

std::string_view topic_title(Topic topic) {
    switch (topic) {
        case Topic::Output:
            return "Output and display";
        case Topic::SpatialEncoding:
            return "Spatial encoding (manual part three)";
        case Topic::Specular:
            return "Specular reflection models (-S: only one)";
        case Topic::Lights:
            return "Lights, shadow feelers and attenuation";
        case Topic::Highlights:
            return "Color of specular highlights (-C: only one)";
        case Topic::Disable:
            return "Disable (-D: not mutually exclusive)";
        case Topic::FileFormat:
            return "File formats (manual 2.2 to 2.5)";
        case Topic::Illumination:
            return "Illumination model";
        case Topic::AdaptiveSampling:
            return "Chi-square adaptive sampling (-X)";
        case Topic::OldVersions:
            return "Old versions (-O)";
        case Topic::Debugging:
            return "Debug switches (-d)";
        case Topic::Program:
            return "Program options (new in this version)";
    }
    return "";
}

std::string_view exclusive_subject(Exclusive group) {
    switch (group) {
        case Exclusive::SpecularModel:
            return "the specular model";
        case Exclusive::HighlightColor:
            return "the color of specular highlights";
        case Exclusive::PhongShading:
            return "Phong shading";
        case Exclusive::WarnLight:
            return "the Warn light";
        case Exclusive::None:
            break;
    }
    return "";
}

}  // namespace rt
