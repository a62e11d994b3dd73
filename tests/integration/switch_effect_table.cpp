#include "switch_effect_table.h"

namespace rt::test {

namespace {

// Regions of scenes/gallery.scn (160 x 120), and of its variants, which share its geometry.
const std::vector<Region> gallery_regions{
    {"all", 0, 0, 159, 119},         {"top_rows", 0, 0, 159, 20},
    {"mirror", 16, 42, 38, 72},      {"mirror_top", 14, 37, 40, 50},
    {"mirror_low", 14, 56, 30, 76},  {"wall", 75, 5, 95, 20},
    {"wall_shadow", 71, 35, 85, 49}, {"wall_edge", 64, 32, 69, 50},
    {"blue", 45, 34, 50, 44},        {"yellow", 103, 35, 107, 39},
    {"pane", 98, 42, 112, 45},       {"sphere", 88, 41, 101, 55},
    {"red", 100, 70, 120, 86},       {"green", 26, 72, 44, 88},
    {"floor", 50, 92, 85, 104},      {"glass_shadow", 100, 92, 135, 100},
    {"right_wall", 130, 5, 155, 60}, {"white_light", 46, 15, 60, 17},
};

// Regions of scenes/highlights.scn (128 x 96).
const std::vector<Region> highlight_regions{
    {"all", 0, 0, 127, 95},         {"upright_peak", 26, 42, 32, 48},
    {"upright_edge", 2, 12, 8, 20}, {"upright_side", 40, 40, 52, 60},
    {"flat_near", 76, 70, 90, 80},  {"flat_far", 110, 66, 125, 72},
    {"light_near", 5, 48, 11, 55},
};

// Regions of scenes/lens.scn (320 x 240): inside the magnifier and inside the amber cylinder lens,
// and the table before and beyond the lenses, where neither the lenses nor their shadows fall.
const std::vector<Region> lens_regions{
    {"magnifier", 80, 85, 150, 150},
    {"cylinder", 180, 85, 255, 150},
    {"table_near", 40, 200, 280, 235},
    {"table_far", 60, 40, 260, 70},
};

// Display (gallery).
std::vector<PictureRow> display_rows() {
    using enum Effect;
    return {
        {"-m",
         {"-m0.5"},
         "gallery",
         {{"wall", DisplayRatio, 0.45, 0.55}, {"floor", DisplayRatio, 0.45, 0.55}, {"all", Same}},
         "-m multiplies the display values; the intensities (.gro) stay as they are"},
        {"-c",
         {"-c"},
         "gallery",
         {{"yellow", DisplayChanges, 0.5}, {"wall", DisplayRatio, 0.999, 1.001}, {"all", Same}},
         "-c stops clipping: the yellow light, over 255, shows strange colours; the rest does not "
         "change"},
    };
}

// Lights, attenuation and shadow feelers (gallery).
std::vector<PictureRow> light_rows() {
    using enum Effect;
    return {
        {"-A",
         {"-A10,1"},
         "gallery",
         {{"blue", Darker, 40.0},
          {"white_light", Darker, 100.0},
          {"floor", Within, -115.0, -100.0}},
         "-A10,1: intensity divided by dist/10 + 1, even the lights seen directly"},
        {"-Da",
         {"-Da"},
         "gallery",
         {{"blue", Brighter, 6.0}, {"glass_shadow", Brighter, 4.0}},
         "-Da: rays do not attenuate with distance, so even the lights seen directly brighten"},
        {"-Dl",
         {"-Dl"},
         "gallery",
         {{"floor", Brighter, 3.0}, {"wall", Brighter, 3.0}, {"blue", Within, -1.0, 1.0}},
         "-Dl: shadow feelers do not attenuate: lit surfaces brighten, lights seen directly do "
         "not"},
        {"-T",
         {"-T"},
         "gallery",
         {{"yellow", Brighter, 60.0}, {"wall", Same}, {"mirror", Same}},
         "-T: the yellow light behind the glass pane shines through it toward the eye"},
        {"-Dt",
         {"-Dt"},
         "gallery",
         {{"glass_shadow", Darker, 25.0}, {"wall", Same}},
         "-Dt: shadow feelers stop at the horizontal glass pane, whose shadow darkens"},
        {"-Ds",
         {"-Ds"},
         "gallery",
         {{"floor", Within, -132.0, -115.0}, {"wall", Darker, 120.0}},
         "-Ds: no shadow feelers; the small lights are found only by diffuse rays"},
        {"-Db",
         {"-Db"},
         "gallery",
         {{"blue", Darker, 40.0}, {"wall", Darker, 100.0}, {"yellow", Within, -6.0, 0.0}},
         "-Db: only the outside of an emitter emits: the blue light, seen from behind, goes dark, "
         "and the wall behind the yellow light loses its light; the yellow light itself, seen "
         "from the front, hardly changes"},
        {"-Wr",
         {"-Wr"},
         "gallery",
         {{"floor", Within, -62.0, -49.0},
          {"mirror", Within, -143.0, -127.0},
          {"wall", Darker, 120.0}},
         "-Wr: each feeler weighted by cos^N of its angle to the emitter's normal"},
        {"-Wc",
         {"-Wc", "0.5"},
         "gallery",
         {{"floor", Within, -100.0, -85.0},
          {"wall", Darker, 120.0},
          {"white_light", Within, -30.0, -5.0}},
         "-Wc 0.5: as -Wr, and no light beyond 0.5 radians of the emitter's normal; the white "
         "light seen directly darkens a little"},
        {"-Wt",
         {"-Wt1.0"},
         "gallery",
         {{"floor", Within, -50.0, -40.0},
          {"mirror", Within, -160.0, -145.0},
          {"wall", Darker, 120.0}},
         "-Wt1.0: light only where the line to the source, displaced 1.0 behind the emitter, "
         "crosses it"},
        {"-F",
         {"-F0.1,4"},
         "gallery",
         {{"wall_shadow", Brighter, 6.0}, {"wall", Within, -1.0, 1.0}},
         "-F0.1,4: four feelers per light, turned by up to 0.1 radians: the shadow of the "
         "floating cube grows soft"},
        {"-K",
         {"-K"},
         "gallery",
         {{"yellow", Darker, 60.0}, {"white_light", Within, -20.0, 0.0}},
         "-K: weights scaled so nothing need be clipped: the yellow light (e = 1.5) dims to 1, the "
         "white light (e = 1) stays"},
    };
}

// The ray tree (gallery).
std::vector<PictureRow> ray_tree_rows() {
    using enum Effect;
    return {
        {"-Dr",
         {"-Dr"},
         "gallery",
         {{"mirror", Darker, 100.0}, {"wall", Same}, {"floor", Same}},
         "-Dr: no reflected rays: the mirror shows only its own dim colour"},
        {"-Dd",
         {"-Dd"},
         "gallery",
         {{"mirror", Changes, 0.85}, {"mirror_low", Brighter, 6.0}, {"wall_shadow", Same}},
         "-Dd: one reflected ray: the blurred mirror turns sharp"},
        {"-I",
         {"-I"},
         "gallery",
         {{"mirror_low", Brighter, 3.0}, {"mirror", Changes, 0.4, 0.8}, {"wall", Same}},
         "-I: the mirror's distributed rays get the full illumination model"},
        {"-Oi",
         {"-Oi"},
         "gallery",
         {{"glass_shadow", Darker, 20.0}, {"wall", Brighter, 15.0}},
         "-Oi: the earliest model: no attenuation, and feelers that stop at the glass",
         {"-O1"}},
        {"-O1",
         {"-O1"},
         "gallery",
         {{"all", Same}},
         "-O1: the early version is -Oi taking every sample (docs/rendering.md)",
         {},
         {"-Oi", "-Dx"}},
    };
}

// Sampling (gallery).
std::vector<PictureRow> sampling_rows() {
    using enum Effect;
    return {
        {"-Dx",
         {"-Dx"},
         "gallery",
         {{"wall_shadow", Touches, 0.5}, {"mirror", Same, 0.02}},
         "-Dx: every sample, also where the rule would stop early (flat walls)"},
        {"-Xp",
         {"-Xp0.9,50"},
         "gallery",
         {{"right_wall", Changes, 0.3}, {"blue", Same, 0.2}, {"wall_shadow", Within, -1.0, 1.0}},
         "-Xp0.9,50: pixels stop sampling sooner where their samples differ (lit edges)"},
        {"-Xr",
         {"-Xr0.05,0.001"},
         "gallery",
         {{"yellow", Touches, 0.3},
          {"yellow", Within, -0.5, 0.5},
          {"mirror", Same},
          {"wall_shadow", Same}},
         "-Xr0.05,0.001: a stricter rule for distributed rays: the frosted pane's refracted rays, "
         "which stop early where they all meet the yellow light, are all taken"},
        {"--seed",
         {"--seed", "7"},
         "gallery",
         {{"wall", Touches, 0.9},
          {"mirror", Changes, 0.8},
          {"wall", Within, -1.0, 1.0},
          {"mirror", Within, -3.0, 3.0}},
         "another seed: every jittered sample moves"},
    };
}

// Intersection (gallery: an octree of depth 4).
std::vector<PictureRow> intersection_rows() {
    using enum Effect;
    return {
        {"-tv",
         {"-tv1"},
         "gallery",
         {{"yellow", Darker, 170.0}, {"glass_shadow", Brighter, 4.0}},
         "-tv1: rays end after one fruitless voxel: most of the scene goes dark, and feelers cut "
         "short let their light through, so the glass pane's shadow goes"},
        {"-on",
         {"-on"},
         "gallery",
         {{"right_wall", Brighter, 3.0}, {"wall", Same}},
         "-on: near hits accepted unverified: some rays miss a nearer polygon in a later voxel"},
    };
}

// Highlights (highlights.scn).
std::vector<PictureRow> highlight_rows() {
    using enum Effect;
    return {
        {"-Sp", {"-Sp"}, "highlights", {{"all", Same}}, "-Sp is the default"},
        {"-Ci", {"-Ci"}, "highlights", {{"all", Same}}, "-Ci is the default"},
        {"-Sg",
         {"-Sg"},
         "highlights",
         {{"flat_far", Darker, 8.0}, {"flat_near", Same}, {"upright_peak", Same}},
         "-Sg: the geometric attenuation dims the grazing highlight only"},
        {"-Stg",
         {"-Stg1.5"},
         "highlights",
         {{"upright_peak", Within, -127.0, -118.0}, {"upright_edge", Within, 9.5, 14.0}},
         "-Stg1.5: Torrance-Sparrow with Gaussian facets: a dim broad highlight"},
        {"-Stb",
         {"-Stb1.5"},
         "highlights",
         {{"upright_peak", Within, -136.0, -127.5}, {"upright_edge", Within, 4.5, 9.3}},
         "-Stb1.5: Beckmann facets: dimmer at the peak than Gaussian, and at the edge too"},
        {"-Co",
         {"-Co"},
         "highlights",
         {{"flat_near", Within, -128.0, -118.0, 2},
          {"flat_near", Within, -30.0, -20.0, 0},
          {"upright_peak", Within, -16.0, -11.0}},
         "-Co: highlights filtered by the object's colour: the orange panel's lose their blue"},
        {"-Cf",
         {"-Cf"},
         "highlights",
         {{"flat_near", Within, -115.0, -105.0, 2},
          {"flat_near", Within, -39.0, -30.0, 0},
          {"upright_peak", Within, -16.0, -11.0}},
         "-Cf: Fresnel per channel: the orange panel's grazing highlight keeps some blue"},
    };
}

// Smooth shading (the gallery with the smooth-shade field).
std::vector<PictureRow> smooth_shading_rows() {
    using enum Effect;
    return {
        {"-Po",
         {"-Po"},
         "smooth",
         {{"yellow", Darker, 100.0}, {"wall", Same}},
         "-Po: the smooth-shaded glass pane turns opaque and hides the yellow light",
         {},
         {"-Pt"}},
        {"-Ot",
         {"-Pt", "-Ot"},
         "smooth",
         {{"red", Darker, 3.0},
          {"red", Changes, 0.05, 0.5},
          {"mirror_low", Darker, 1.5},
          {"wall", Same}},
         "-Ot: no correction where the smooth red cube's normals face away from the ray",
         {},
         {"-Pt"}},
        {"-E",
         {"-Pt", "-E0.1"},
         "smooth",
         {{"red", Brighter, 4.0}, {"red", Changes, 0.8}, {"sphere", Changes, 0.8}, {"wall", Same}},
         "-E0.1: sharp breaks between faces more than 0.1 radians apart",
         {},
         {"-Pt"}},
    };
}

// File formats that change the picture.
std::vector<PictureRow> format_rows() {
    using enum Effect;
    return {
        {"-M",
         {},
         "marked",
         {{"sphere", Changes, 0.8}, {"wall", Same}},
         "-M: the sphere's polygons, marked 2, take their normals from the sphere of the shape "
         "file",
         {},
         {},
         "marked-plain"},
        {"-R",
         {},
         "rgb-spread",
         {{"pane", Changes, 0.25}, {"wall", Same}},
         "-R: three indices of refraction: the glass pane splits the colours",
         {},
         {},
         "rgb-equal"},
        {"-V",
         {},
         "lens",
         {{"magnifier", Changes, 0.9},
          {"cylinder", Changes, 0.9},
          {"cylinder", Darker, 20.0, 1.0, 2},
          {"table_near", Same},
          {"table_far", Same}},
         "-V: the lenses' curved faces are read: the table seen through them is magnified, and "
         "stretched across the cylinder's axis and tinted amber by its texture map",
         {},
         {},
         "lens-plain"},
    };
}

// Switches that must leave the picture alone.
std::vector<PictureRow> same_picture_rows() {
    using enum Effect;
    return {
        {"-od", {"-od6"}, "gallery", {{"all", Same}}, "-od6: another octree depth, same picture"},
        {"-ol", {"-ol20"}, "gallery", {{"all", Same}}, "-ol20: a smaller octlist, same picture"},
        {"-ss", {"-ss4"}, "gallery", {{"all", Same}}, "-ss4: a smaller seed size, same picture"},
        {"-op", {"-op"}, "gallery", {{"all", Same}}, "-op: the level-order fill, the same tree"},
        {"-of",
         {"-of"},
         "gallery",
         {{"all", Same}},
         "-of: no fudge; here no ray meets a voxel face so closely that it matters"},
        // These four name the method they built in -p's profile, so that a dropped switch shows.
        {"-De",
         {"-p", "-De"},
         "gallery",
         {{"all", Same}},
         "-De: no exit culling, same picture",
         {},
         {"-p"},
         {},
         "profile: octree over 224 polygons"},
        {"--accel",
         {"-p", "--accel", "bvh"},
         "gallery",
         {{"all", Same}},
         "any method, same picture",
         {},
         {"-p"},
         {},
         "profile: exit culling over bvh over"},
        {"--accel",
         {"-p", "--accel", "seads"},
         "gallery",
         {{"all", Same}},
         "any method, same picture",
         {},
         {"-p"},
         {},
         "profile: exit culling over SEADS"},
        {"--accel",
         {"-p", "-L20", "--accel", "brute"},
         "gallery",
         {{"top_rows", Same}},
         "any method, same picture (brute force is slow: the top rows only)",
         {},
         {"-p", "-L20"},
         {},
         "profile: exit culling over brute force"},
        {"--zbuffer",
         {"-p", "--zbuffer"},
         "gallery",
         {{"all", Same}},
         "z-buffer first hits, same picture",
         {},
         {"-p"},
         {},
         "profile: z-buffer first hits over exit culling over octree"},
        {"--threads",
         {"--threads", "3"},
         "gallery",
         {{"all", Same}},
         "any number of threads, same picture"},
    };
}

// The wireframe (docs/wireframe.md): no ray is traced.
std::vector<PictureRow> wireframe_rows() {
    using enum Effect;
    return {
        {"-w",
         {"-w"},
         "gallery",
         {{"all", DisplayRatio, 0.0, 0.3},
          {"wall", DisplayRatio, 0.0, 0.01},
          {"white_light", Darker, 100.0},
          {"mirror", Darker, 50.0},
          {"floor", Darker, 60.0}},
         "-w: the wireframe only, black but for the lines: the lights, the mirror, the floor "
         "(but for its grid) and the wall (no edge crosses it) go dark"},
        {"-oo",
         {"-w", "-oo"},
         "gallery",
         {{"all", Brighter, 1.0}, {"all", Brighter, 30.0, 1.0, 2}, {"all", Changes, 0.02, 0.5}},
         "-oo: the octree's boxes, blue, added to the wireframe",
         {},
         {"-w"}},
    };
}

// Debugging switches: they print, and leave the picture alone.
std::vector<PictureRow> debugging_rows() {
    using enum Effect;
    return {
        {"-dc",
         {"-dc"},
         "gallery",
         {{"all", Same}},
         "-dc prints each pixel's column",
         {},
         {},
         {},
         "line 119 column 0"},
        {"-dof",
         {"-op", "-dof"},
         "gallery",
         {{"all", Same}},
         "-dof traces the fill-plane octree build",
         {},
         {"-op"},
         {},
         "fill-plane level 4: 32 nodes"},
        {"-df",
         {"-df"},
         "gallery",
         {{"all", Same}},
         "-df traces the parsing",
         {},
         {},
         {},
         "header: center 0 lghtick 2 sptncde 1 octr 4"},
        {"-dd",
         {"-dd"},
         "gallery",
         {{"all", Same}},
         "-dd prints the colour map and the pixels",
         {},
         {},
         {},
         "color map: display value = intensity x 255 x 1"},
        {"-dx",
         {"-dx"},
         "gallery",
         {{"all", Same}},
         "-dx prints each pixel's samples",
         {},
         {},
         {},
         "pixel 0 119: 2 samples"},
        {"-de",
         {"-de"},
         "gallery",
         {{"all", Same}},
         "-de checks the culled rays",
         {},
         {},
         {},
         "culled rays re-traced, 0 hit something"},
        {"-p",
         {"-p"},
         "gallery",
         {{"all", Same}},
         "-p prints the profile",
         {},
         {},
         {},
         "profile: exit culling over octree over 224 polygons"},
    };
}

// The strike check and -dl: slow or wordy, so drawn for the top rows only.
std::vector<PictureRow> strike_rows() {
    using enum Effect;
    return {
        {"-ds",
         {"-ds", "-L20"},
         "gallery",
         {{"top_rows", Same}},
         "-ds checks every ray by brute force",
         {},
         {"-L20"},
         {},
         "strike check (-ds): 0 of"},
        {"-dsp",
         {"-dsp", "-L20"},
         "gallery",
         {{"top_rows", Same}},
         "-dsp implies -ds",
         {},
         {"-L20"},
         {},
         "strike check (-ds): 0 of"},
        {"-dso",
         {"-dso", "-L20"},
         "gallery",
         {{"top_rows", Same}},
         "-dso implies -ds",
         {},
         {"-L20"},
         {},
         "strike check (-ds): 0 of"},
        {"-dl",
         {"-dl", "-L20"},
         "gallery",
         {{"top_rows", Same}},
         "-dl prints every intersection query",
         {},
         {"-L20"},
         {},
         "intersection: origin"},
    };
}

// File formats that must read the same scene.
std::vector<PictureRow> same_scene_rows() {
    using enum Effect;
    return {
        {"-Df",
         {},
         "inline",
         {{"all", Same}},
         "-Df: the attributes inline, the same picture",
         {},
         {},
         "gallery"},
        {"-Dp",
         {},
         "no-power",
         {{"all", Same}},
         "-Dp: pow and tpow absent, taken as 2.0",
         {},
         {},
         "power-two"},
        {"-Of",
         {},
         "old-format",
         {{"all", Same}},
         "-Of: -Df and -Dp together",
         {},
         {},
         "power-two"},
        {"-R",
         {},
         "rgb-equal",
         {{"all", Same}},
         "-R: three equal indices are one index",
         {},
         {},
         "gallery"},
        {"-Pt",
         {"-Pt"},
         "flat-field",
         {{"all", Same}},
         "-Pt: the smooth-shade field read; all zero, nothing is smooth",
         {},
         {},
         "gallery"},
        {"-Po",
         {"-Po"},
         "flat-field",
         {{"all", Same}},
         "-Po: the smooth-shade field read; all zero, nothing is forced opaque",
         {},
         {},
         "gallery"},
        {"-M",
         {},
         "marked-plain",
         {{"all", Same}},
         "-M: marks and a shape file read; every mark 0 changes nothing",
         {},
         {},
         "gallery"},
    };
}

}  // namespace

const std::vector<TestScene>& test_scenes() {
    static const std::vector<TestScene> all{
        {"gallery", "gallery.scn", "original", {}, gallery_regions},
        {"highlights", "highlights.scn", "original", {}, highlight_regions},
        {"smooth", "gallery.scn", "smooth", {}, gallery_regions},
        {"flat-field", "gallery.scn", "flat-field", {}, gallery_regions},
        {"marked", "gallery.scn", "marked", {"-M"}, gallery_regions},
        {"marked-plain", "gallery.scn", "marked-plain", {"-M"}, gallery_regions},
        {"inline", "gallery.scn", "inline", {"-Df"}, gallery_regions},
        {"no-power", "gallery.scn", "no-power", {"-Dp"}, gallery_regions},
        {"power-two", "gallery.scn", "power-two", {}, gallery_regions},
        {"old-format", "gallery.scn", "old-format", {"-Of"}, gallery_regions},
        {"rgb-equal", "gallery.scn", "rgb-equal", {"-R"}, gallery_regions},
        {"rgb-spread", "gallery.scn", "rgb-spread", {"-R"}, gallery_regions},
        {"lens", "lens.scn", "original", {"-V"}, lens_regions},
        {"lens-plain", "lens.scn", "original", {}, lens_regions},
    };
    return all;
}

const std::vector<PictureRow>& picture_rows() {
    static const std::vector<PictureRow> rows = [] {
        std::vector<PictureRow> all;
        for (auto part :
             {&display_rows, &light_rows, &ray_tree_rows, &sampling_rows, &intersection_rows,
              &highlight_rows, &smooth_shading_rows, &format_rows, &same_picture_rows,
              &debugging_rows, &strike_rows, &same_scene_rows, &wireframe_rows}) {
            const std::vector<PictureRow> some = part();
            all.insert(all.end(), some.begin(), some.end());
        }
        return all;
    }();
    return rows;
}

const std::vector<OtherSwitch>& other_switches() {
    static const std::vector<OtherSwitch> all{
        {"-n", "RtProgram.NoGroWithDashNButOtherOutputsStill: no .gro"},
        {"-r", "RtProfile.DashRFiresRandomRaysAndWritesNoPicture: no picture at all"},
        {"-L", "SwitchEffectTable.LDrawsOnlyFromThatLineUp: a shorter picture"},
        {"-doo", "GridRender tests: writes octree.lst, not a picture"},
        {"-doi",
         "OctreeSession tests and RtOctreeSession: a session on standard input, no picture"},
        {"--output", "every row here: the PPM each picture is read from"},
        {"--model", "ModelProgram tests: a scene of its own, made around the model"},
        {"--resume",
         "InterruptedRender.SigtermExits143AndResumeCompletesItBitForBit: the interrupted "
         "picture completed, the same as an uninterrupted one"},
        {"--cutoff", "RayTreeCutoff tests: far fewer rays on nested glass; at 0 the same picture"},
        {"--help", "RtProgram.HelpAndVersion"},
        {"--version", "RtProgram.HelpAndVersion"},
        {"--quiet", "RtProgram tests: nothing printed"},
        {"--no-window", "Window.NeverWaitsWithoutADisplayOrATerminal: no window, no wait"},
        {"--tile", "TileMerge tests: three parts merged equal the single render, pixel for pixel"},
        {"--max-memory", "RtResources.AViewThatFitsStillRenders: the same picture, or a refusal"},
    };
    return all;
}

}  // namespace rt::test
