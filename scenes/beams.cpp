#include "scenes/beams.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "scenes/color.h"
#include "scenes/detail.h"
#include "scenes/polar_grid.h"
#include "scenes/random.h"

namespace monoplane::scenes {
namespace {

struct BeamsParameters {
    int scaffold_towers;  // free-standing scaffold blocks over the field
    int trusses;          // truss bridges across the view
    BeamTessellation tessellation;
    int ground_sectors;
};

const PerDetail<BeamsParameters> kBeamsParameters = {{
    {24, 5, {8.0f, 8.0f, false}, 48},
    {100, 10, {4.0f, 1.0f, false}, 96},
    {220, 14, {4.0f, 1.2f, true}, 192},
    {520, 20, {4.0f, 0.45f, true}, 384},
    {1040, 28, {4.0f, 0.2f, true}, 512},
}};

// The mono-plane corridor: gates every few metres (spacing growing with depth) carry the rails.
constexpr float kCorridorHalfWidth = 3.0f;
constexpr float kCorridorEnd = 210.0f;  // depth of the last gate
constexpr float kBarHeights[3] = {0.45f, 1.25f, 2.45f};
constexpr float kGateHeight = 3.2f;
constexpr float kOverheadHalfWidth = 4.6f;
constexpr float kOverheadHeight = 4.4f;

// Streams of the seed, one per kind of object (random.h).
enum BeamsStream : std::uint64_t { kRails = 1, kGates, kTrusses, kTowers };

struct Palette {
    std::uint32_t steel, orange, white, blue, yellow, red, ground;
};

Palette palette() {
    return {pack_albedo(from_srgb(0x8a8d91)), pack_albedo(from_srgb(0xd9661f)),
            pack_albedo(from_srgb(0xe4e2dc)), pack_albedo(from_srgb(0x2e4a7d)),
            pack_albedo(from_srgb(0xe0b424)), pack_albedo(from_srgb(0xa8322b)),
            pack_albedo(from_srgb(0x8c8378))};
}

const std::uint32_t kPainted = pack_material({0.45f, 0.06f, 0});
const std::uint32_t kStriped = pack_material({0.45f, 0.06f, 2});
const std::uint32_t kMetal = pack_material({0.3f, 0.25f, 0});

Beam make_beam(glm::vec3 start, glm::vec3 end, float thickness, std::uint32_t albedo,
               std::uint32_t material) {
    Beam beam;
    beam.start = start;
    beam.end = end;
    beam.width = thickness;
    beam.height = thickness;
    beam.albedo_rgba8 = albedo;
    beam.material_packed = material;
    return beam;
}

// Gate depths: 2.5 m, then 30 % further each time, so the spacing looks even in perspective.
std::vector<float> gate_depths() {
    std::vector<float> depths;
    for (float d = 2.5f; d <= kCorridorEnd; d *= 1.3f) depths.push_back(d);
    return depths;
}

void add_corridor(BeamsLayout& layout, std::uint64_t seed) {
    const Palette colours = palette();
    Random random(seed, kRails);
    const std::vector<float> gates = gate_depths();
    const float last_gate = gates.back();

    struct RailSpot {
        float x;
        int bar;    // which crossbar level carries it; -1: lies on the ground; 3: overhead
        bool near;  // starts within arm's length
    };
    constexpr RailSpot kSpots[] = {
        {-2.1f, 0, true},
        {1.7f, 0, false},
        {-0.65f, 1, true},
        {0.75f, 1, true},
        {-1.6f, 1, false},
        {-1.3f, 2, true},
        {2.2f, 2, false},
        {0.2f, 2, false},
        {-3.9f, -1, true},
        {3.8f, -1, true},
        {-5.6f, -1, false},
        {5.5f, -1, false},
        {-kOverheadHalfWidth, 3, false},
        {kOverheadHalfWidth, 3, false},
    };
    const std::uint32_t rail_colours[] = {colours.orange, colours.white, colours.yellow};
    int rail_number = 0;
    for (const RailSpot& spot : kSpots) {
        const float thickness = random.uniform(0.06f, 0.12f);
        float y = 0.5f * thickness;  // lying on the ground
        if (spot.bar >= 0 && spot.bar < 3) {
            y = kBarHeights[spot.bar] + 0.5f * (0.09f + thickness);  // resting on the crossbar
        } else if (spot.bar == 3) {
            y = kOverheadHeight + 0.5f * (0.12f + thickness);
        }
        const float start = spot.near ? random.uniform(0.5f, 1.8f) : random.uniform(2.5f, 12.0f);
        const float end = last_gate + random.uniform(0.0f, 20.0f);
        // The outer ground rails splay out a little: lines along, but not exactly along, -z.
        const float splay = spot.bar == -1 && !spot.near ? std::copysign(2.5f, spot.x) : 0.0f;
        const std::uint32_t colour = rail_colours[rail_number % 3];
        const std::uint32_t material = rail_number % 2 == 0 ? kStriped : kPainted;
        Beam rail =
            make_beam({spot.x, y, -start}, {spot.x + splay, y, -end}, thickness, colour, material);
        layout.rails.push_back(layout.beams.size());
        layout.beams.push_back(rail);
        ++rail_number;
    }

    // Gates: two posts, three crossbars and a header; every other gate also carries the overhead
    // rails on taller posts.
    for (std::size_t g = 0; g < gates.size(); ++g) {
        const float z = -gates[g];
        const float post = 0.1f + 0.0006f * gates[g];
        for (float side : {-1.0f, 1.0f}) {
            const float x = side * kCorridorHalfWidth;
            layout.beams.push_back(
                make_beam({x, 0.0f, z}, {x, kGateHeight, z}, post, colours.steel, kMetal));
            if (g % 2 == 0) {
                const float xo = side * kOverheadHalfWidth;
                layout.beams.push_back(make_beam({xo, 0.0f, z}, {xo, kOverheadHeight + 0.06f, z},
                                                 post, colours.steel, kMetal));
            }
        }
        for (const float bar : kBarHeights) {
            layout.beams.push_back(make_beam({-kCorridorHalfWidth, bar, z},
                                             {kCorridorHalfWidth, bar, z}, 0.09f, colours.steel,
                                             kMetal));
        }
        layout.beams.push_back(make_beam({-kCorridorHalfWidth - 0.3f, kGateHeight, z},
                                         {kCorridorHalfWidth + 0.3f, kGateHeight, z}, post,
                                         colours.blue, kPainted));
        if (g % 2 == 0) {
            layout.beams.push_back(make_beam({-kOverheadHalfWidth, kOverheadHeight, z},
                                             {kOverheadHalfWidth, kOverheadHeight, z}, 0.12f,
                                             colours.blue, kPainted));
        }
    }
}

// Keeps the scaffold towers out of the corridor, the trusses' feet and each other.
struct Obstacle {
    glm::vec2 centre;  // (x, z)
    float radius;
};

bool inside_corridor(glm::vec2 centre, float radius) {
    const float depth = -centre.y;
    const float half_width = 7.0f + 0.025f * std::max(depth, 0.0f);
    return depth + radius > -2.0f && depth - radius < kCorridorEnd + 25.0f &&
           std::fabs(centre.x) - radius < half_width;
}

bool overlaps(const std::vector<Obstacle>& obstacles, glm::vec2 centre, float radius) {
    return std::any_of(obstacles.begin(), obstacles.end(), [&](const Obstacle& o) {
        return glm::length(o.centre - centre) < o.radius + radius;
    });
}

float truss_height(float depth) {
    return 5.0f + 0.05f * depth;
}

// Truss bridges across the view: top and bottom chords with verticals and diagonals between
// them, on two posts, at depths spread uniformly from 12 m to 180 m (stratified; papers/000
// Sect. 6: geometry uniformly distributed across space).
void add_trusses(BeamsLayout& layout, int count, std::uint64_t seed, std::vector<Obstacle>& feet) {
    const Palette colours = palette();
    Random random(seed, kTrusses);
    for (int i = 0; i < count; ++i) {
        const float stratum =
            (static_cast<float>(i) + random.uniform(0.1f, 0.9f)) / static_cast<float>(count);
        const float depth = 12.0f + (180.0f - 12.0f) * stratum;
        const float half_span = 10.0f + 0.3f * depth * random.uniform(0.8f, 1.2f);
        const float centre_x = random.uniform(-0.3f, 0.3f) * depth;
        const float bottom = truss_height(depth) * random.uniform(1.0f, 1.25f);
        const float depth_of_truss = 0.8f + 0.012f * depth;
        const float thickness = std::min(0.3f, 0.1f + 0.0012f * depth);
        const float z = -depth;
        const float top = bottom + depth_of_truss;
        const std::uint32_t colour = i % 2 == 0 ? colours.red : colours.blue;
        const float left = centre_x - half_span;
        const float right = centre_x + half_span;
        layout.beams.push_back(
            make_beam({left, bottom, z}, {right, bottom, z}, thickness, colour, kPainted));
        layout.beams.push_back(
            make_beam({left, top, z}, {right, top, z}, thickness, colour, kPainted));
        const int panels =
            std::max(2, static_cast<int>(std::round(2.0f * half_span / depth_of_truss)));
        const float panel = 2.0f * half_span / static_cast<float>(panels);
        for (int p = 0; p <= panels; ++p) {
            const float x = left + panel * static_cast<float>(p);
            layout.beams.push_back(
                make_beam({x, bottom, z}, {x, top, z}, 0.7f * thickness, colour, kPainted));
            if (p < panels) {
                const bool rising = p < panels / 2;  // diagonals mirror about the middle
                const glm::vec3 a{x, rising ? bottom : top, z};
                const glm::vec3 b{x + panel, rising ? top : bottom, z};
                layout.beams.push_back(make_beam(a, b, 0.6f * thickness, colour, kPainted));
            }
        }
        for (const float x : {left, right}) {
            layout.beams.push_back(make_beam({x, 0.0f, z}, {x, top + 0.2f, z}, 1.6f * thickness,
                                             colours.steel, kMetal));
            feet.push_back({{x, z}, 1.5f});
        }
    }
}

// A free-standing scaffold tower: posts on a grid of cells_x x cells_z cells, turned by its yaw
// about its centre, with `levels` storeys of ledgers and transoms.
struct ScaffoldTower {
    float distance = 0.0f;   // from the viewer, over the ground
    glm::vec2 centre{0.0f};  // (x, z)
    float cell = 0.0f;       // metres between posts
    int cells_x = 1;
    int cells_z = 1;
    float radius = 0.0f;  // of the footprint, with a margin
    float level_height = 0.0f;
    int levels = 1;
    float cos_yaw = 1.0f;
    float sin_yaw = 0.0f;
    float thickness = 0.0f;
    std::uint32_t colour = 0;
    std::uint32_t material = 0;

    // Post (ix, iz) of the grid at height y.
    glm::vec3 at(int ix, int iz, float y) const {
        const float lx = (static_cast<float>(ix) - 0.5f * static_cast<float>(cells_x)) * cell;
        const float lz = (static_cast<float>(iz) - 0.5f * static_cast<float>(cells_z)) * cell;
        return glm::vec3(centre.x + cos_yaw * lx + sin_yaw * lz, y,
                         centre.y - sin_yaw * lx + cos_yaw * lz);
    }
};

// Where tower i of `count` might stand, and how big it is: stratified uniform in distance
// (papers/000 Sect. 6: geometry uniformly distributed across space); the corridor and its rails
// supply the near range. Sized with the distance so far towers stay visible.
ScaffoldTower propose_tower(Random& random, int i, int count) {
    ScaffoldTower tower;
    const float u =
        (static_cast<float>(i) + random.uniform(0.0f, 1.0f)) / static_cast<float>(count);
    tower.distance = 4.0f + 256.0f * u;
    const bool ahead = random.chance(0.85);
    const float bearing = ahead ? random.uniform(-1.2f, 1.2f)
                                : random.uniform(-static_cast<float>(std::numbers::pi),
                                                 static_cast<float>(std::numbers::pi));
    tower.centre = {tower.distance * std::sin(bearing), -tower.distance * std::cos(bearing)};
    tower.cell = (1.5f + 0.03f * tower.distance) * random.uniform(0.8f, 1.2f);
    tower.cells_x = random.uniform_int(1, 3);
    tower.cells_z = random.uniform_int(1, 3);
    tower.radius =
        0.5f * tower.cell *
            std::hypot(static_cast<float>(tower.cells_x), static_cast<float>(tower.cells_z)) +
        0.5f;
    return tower;
}

// A placed tower's storeys (below the trusses at its distance), orientation and paint.
void style_tower(Random& random, const Palette& colours, ScaffoldTower& tower) {
    const std::uint32_t tower_colours[] = {colours.steel, colours.orange, colours.white,
                                           colours.yellow, colours.steel};
    tower.level_height = tower.cell * random.uniform(0.7f, 1.0f);
    const float ceiling = std::max(tower.level_height, truss_height(tower.distance) - 1.5f);
    tower.levels = std::max(
        1, std::min(random.uniform_int(1, 4), static_cast<int>(ceiling / tower.level_height)));
    const float yaw = random.chance(0.5) ? 0.0f : random.uniform(0.0f, 1.5f);
    tower.thickness =
        std::clamp((0.07f + 0.0012f * tower.distance) * random.uniform(0.8f, 1.25f), 0.05f, 0.3f);
    tower.colour = tower_colours[random.uniform_int(0, 4)];
    tower.material = random.chance(0.25) ? kStriped : kPainted;
    tower.cos_yaw = std::cos(yaw);
    tower.sin_yaw = std::sin(yaw);
}

// The posts, from the ground to a little above the top storey.
void add_tower_posts(BeamsLayout& layout, const ScaffoldTower& tower) {
    const float top = static_cast<float>(tower.levels) * tower.level_height;
    for (int ix = 0; ix <= tower.cells_x; ++ix) {
        for (int iz = 0; iz <= tower.cells_z; ++iz) {
            layout.beams.push_back(make_beam(tower.at(ix, iz, 0.0f),
                                             tower.at(ix, iz, top + 0.3f * tower.level_height),
                                             1.2f * tower.thickness, tower.colour, tower.material));
        }
    }
}

// Ledgers and transoms at every level between neighbouring posts, and on the outer faces a
// diagonal brace down to the level below about every other bay.
void add_tower_levels(BeamsLayout& layout, const ScaffoldTower& tower, Random& random) {
    const float thickness = tower.thickness;
    for (int level = 1; level <= tower.levels; ++level) {
        const float y = static_cast<float>(level) * tower.level_height;
        const float below = y - tower.level_height;
        for (int ix = 0; ix <= tower.cells_x; ++ix) {
            for (int iz = 0; iz <= tower.cells_z; ++iz) {
                const bool outer_x = ix == 0 || ix == tower.cells_x;
                const bool outer_z = iz == 0 || iz == tower.cells_z;
                if (ix < tower.cells_x) {
                    layout.beams.push_back(make_beam(tower.at(ix, iz, y), tower.at(ix + 1, iz, y),
                                                     thickness, tower.colour, tower.material));
                    if (outer_z && random.chance(0.5)) {
                        const bool flip = random.chance(0.5);
                        layout.beams.push_back(make_beam(tower.at(ix, iz, flip ? y : below),
                                                         tower.at(ix + 1, iz, flip ? below : y),
                                                         0.8f * thickness, tower.colour,
                                                         tower.material));
                    }
                }
                if (iz < tower.cells_z) {
                    layout.beams.push_back(make_beam(tower.at(ix, iz, y), tower.at(ix, iz + 1, y),
                                                     thickness, tower.colour, tower.material));
                    if (outer_x && random.chance(0.5)) {
                        const bool flip = random.chance(0.5);
                        layout.beams.push_back(make_beam(tower.at(ix, iz, flip ? y : below),
                                                         tower.at(ix, iz + 1, flip ? below : y),
                                                         0.8f * thickness, tower.colour,
                                                         tower.material));
                    }
                }
            }
        }
    }
}

// Free-standing scaffold towers kept clear of the corridor, the obstacles and each other: each
// tower tries up to 40 places.
void add_towers(BeamsLayout& layout, int count, std::uint64_t seed,
                std::vector<Obstacle> obstacles) {
    const Palette colours = palette();
    Random random(seed, kTowers);
    for (int i = 0; i < count; ++i) {
        for (int attempt = 0; attempt < 40; ++attempt) {
            ScaffoldTower tower = propose_tower(random, i, count);
            if (inside_corridor(tower.centre, tower.radius) ||
                overlaps(obstacles, tower.centre, tower.radius)) {
                continue;
            }
            obstacles.push_back({tower.centre, tower.radius});
            style_tower(random, colours, tower);
            add_tower_posts(layout, tower);
            add_tower_levels(layout, tower, random);
            break;
        }
    }
}

}  // namespace

BeamsLayout beams_layout(Detail detail, std::uint64_t seed) {
    const BeamsParameters& parameters = for_detail(kBeamsParameters, detail);
    BeamsLayout layout;
    add_corridor(layout, seed);
    std::vector<Obstacle> obstacles;
    add_trusses(layout, parameters.trusses, seed, obstacles);
    add_towers(layout, parameters.scaffold_towers, seed, obstacles);
    return layout;
}

Scene generate_beams(Detail detail, std::uint64_t seed) {
    const BeamsParameters& parameters = for_detail(kBeamsParameters, detail);
    const BeamsLayout layout = beams_layout(detail, seed);

    ChunkBuilder builder(chunk_triangle_target(detail));
    PolarGrid ground;
    ground.sectors = parameters.ground_sectors;
    ground.outer_radius = 700.0f;
    SurfaceLook concrete;
    concrete.albedo_rgba8 = palette().ground;
    concrete.material_packed = pack_material({0.85f, 0.03f, 1});
    add_polar_grid(
        builder, ground, [](glm::vec2) { return 0.0f; },
        [&](glm::vec3, glm::vec3) { return concrete; });
    for (const Beam& beam : layout.beams) add_beam(builder, beam, parameters.tessellation);

    Scene scene;
    scene.id = SceneId::Beams;
    scene.detail = detail;
    scene.seed = seed;
    builder.build_into(scene);
    scene.viewpoints = {
        make_viewpoint("default", {0.0, 1.7, 0.0}),
        // Raised and stepped back: the corridor and the field ahead fill the view.
        make_viewpoint("bench-forward", {0.0, 2.4, 1.5}, 0.0, -4.0),
        // Crouching, looking down the rails: most geometry near, stereo-heavy.
        make_viewpoint("bench-ground", {0.3, 0.9, 0.0}, 0.0, -15.0),
        // Turned left across the scaffold field: many edges at an angle.
        make_viewpoint("bench-side", {0.0, 1.7, 0.0}, 50.0, 0.0),
    };
    scene.lighting.sun_direction = glm::normalize(glm::vec3(-0.45f, 0.75f, 0.5f));
    scene.lighting.sun_radiance = {3.1f, 2.95f, 2.7f};
    scene.lighting.sky_zenith = {0.17f, 0.35f, 0.74f};
    scene.lighting.sky_horizon = {0.72f, 0.80f, 0.90f};
    scene.lighting.ground_albedo = {0.27f, 0.25f, 0.22f};
    return scene;
}

}  // namespace monoplane::scenes
