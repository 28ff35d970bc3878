#include "bench/bench_cycles.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <tbb/info.h>

#include "bench/bench_convergence.h"
#include "bench/bench_output.h"
#include "bench/bench_process.h"
#include "bench/bench_race.h"
#include "bench/cycles_comparison.h"
#include "bench/cycles_inputs.h"
#include "bench/cycles_script.h"
#include "bench/reference_cache.h"
#include "bench/strata_child.h"
#include "film/image_metrics.h"
#include "integrator/progressive_renderer.h"
#include "io/image_io.h"
#include "io/output_file.h"
#include "scene/scene_loader.h"
#include "util/error.h"

namespace strata {
namespace {

namespace fs = std::filesystem;

// The reference has 16x the samples of the largest Cycles render, as the bench's other
// references have of its largest checkpoint.
constexpr int kReferenceSppFactor = 16;

// Why Cycles cannot be given the scene as Strata renders it, or empty. The script builds diffuse
// materials, textured or not, without vertex colours (a model without materials keeps Cycles'
// default surface, Lambertian 0.8 like Strata's), or a GGX lobe without Fresnel, with one-sided
// emission; keeps the model's vertex normals; and lights the scene by its emitters, a uniform sky
// or a map, nothing else.
std::string unsupported(const MeshData& mesh, bool lit) {
    if (!mesh.pointLights.empty() || !mesh.spotLights.empty() || !mesh.directionalLights.empty()) {
        return "it has point, spot or directional lights";
    }
    if (!mesh.colours.empty()) return "it has vertex colours";
    bool emits = false;
    for (const Material& m : mesh.materials) {
        if (m.transmission > 0.0f || m.clearcoat > 0.0f) return "material " + m.name + " transmits or is coated";
        // Cycles 3.4's Principled sheen is Burley's, not the Charlie lobe; an unlit surface would
        // be its default Lambertian.
        if (m.sheenColour != glm::vec3(0.0f)) return "material " + m.name + " has a sheen";
        if (m.unlit) return "material " + m.name + " is unlit";
        // Cycles 3.4's Glossy BSDF has no Fresnel and no diffuse base under it: only Strata's
        // layered model at Kd 0 and F0 = Ks = 1 (Schlick's F is then 1) is the same BRDF.
        if (m.specular != glm::vec3(0.0f) && (m.specular != glm::vec3(1.0f) || m.diffuse != glm::vec3(0.0f))) {
            return "material " + m.name + " is glossy other than a white conductor (Cycles' GGX has no Fresnel)";
        }
        if (m.textures.roughness || m.textures.metallic || m.textures.transmission || m.textures.clearcoat ||
            m.textures.clearcoatRoughness || m.textures.specularGlossiness || m.textures.emission ||
            m.textures.coverage || m.textures.normal ||
            (m.textures.colour && m.specular != glm::vec3(0.0f))) {
            return "material " + m.name + " has textures other than a diffuse colour";
        }
        emits = emits || m.emission != glm::vec3(0.0f);
    }
    const auto env = mesh.environment.kind;
    if (!(env == Environment::Kind::None || (env == Environment::Kind::Default && (emits || lit)))) {
        return "it is lit by an environment of its own";
    }
    return "";
}

// Each textured material's colour texture, decoded by Strata's texture code, as a linear EXR in
// `dir` (the materials are numbered: their names need not be file names).
std::map<std::string, fs::path> writeColourTextures(const MeshData& mesh, const fs::path& dir) {
    std::map<std::string, fs::path> textures;
    for (size_t i = 0; i < mesh.materials.size(); ++i) {
        const Material& m = mesh.materials[i];
        if (!m.textures.colour) continue;
        fs::create_directories(dir);
        const fs::path exr = dir / ("colour-" + std::to_string(i) + ".exr");
        writeLinearTexture(*m.textures.colour, exr);
        textures[m.name] = exr;
    }
    return textures;
}

int nearestPassMultiple(int spp) {
    return kPathsPerPass * std::max(1, static_cast<int>(std::lround(double(spp) / kPathsPerPass)));
}

glm::dvec3 channelMeans(const Image& image) {
    glm::dvec3 sum(0.0);
    for (const auto& p : image.pixels) sum += glm::dvec3(p.x, p.y, p.z);
    return sum / double(image.pixels.size());
}

// What Strata's defaults are in this build, for the table (another build may have others).
std::string defaultsLabel() {
    const RenderOptions defaults;
    std::string label = "Strata defaults (" + defaults.sampler;
    if (defaults.nee) label += ", NEE";
    if (defaults.rouletteDepth >= 0) label += ", roulette from " + std::to_string(defaults.rouletteDepth);
    return label + ")";
}

// One Strata configuration of the comparison: the options every one of its runs shares.
struct StrataConfig {
    std::string label;
    RenderOptions options;
};

struct CyclesRun {
    int spp = 0;
    fs::path image;
    std::shared_ptr<std::vector<double>> renderSeconds;  // parsed from each run's log
    Entrant entrant;
};

struct StrataRun {
    size_t config = 0;
    int cyclesSpp = 0;
    int spp = 0;
    std::string match;
    fs::path image;
    Entrant entrant;
};

std::string lightingText(const CyclesBenchSettings& settings) {
    if (!settings.environmentMap.empty()) {
        return ", under " + settings.environmentMap.filename().string() +
               (settings.environmentRotation != 0.0f ? cell(" turned %g degrees", settings.environmentRotation)
                                                      : std::string());
    }
    if (settings.sky) {
        return cell(", under a uniform sky of %g %g %g", settings.sky->x, settings.sky->y, settings.sky->z);
    }
    return "";
}

}  // namespace

CyclesComparison runCyclesComparison(const CyclesBenchSettings& settings) {
    const std::string title = "\n### Against Blender's Cycles (" + settings.scene.string() +
                              (settings.whiteMetalRoughness
                                   ? cell(", every material white metal of roughness %g", *settings.whiteMetalRoughness)
                                   : std::string()) +
                              lightingText(settings) + ")\n\n";
    if (!onPath("blender")) {
        std::fprintf(stderr, "note: --vs-cycles skipped: no blender on PATH (scripts/setup.sh --peers)\n");
        return {title + "Skipped: `blender` is not on PATH (Debian package blender; `scripts/setup.sh --peers`).\n",
                {}};
    }
    for (const fs::path& file : {settings.scene, settings.environmentMap}) {
        if (!file.empty() && !fs::is_regular_file(file)) {
            return {title + "Skipped: " + file.string() + " is missing.\n", {}};
        }
    }
    const fs::path& out = settings.outDir;
    fs::create_directories(out);
    // What every render of the comparison shares: the scene and its lighting.
    RenderOptions sceneOptions;
    sceneOptions.scene = settings.scene.string();
    if (settings.whiteMetalRoughness) {
        const fs::path metal = out / (settings.scene.stem().string() + "-white-metal.glb");
        writeWhiteMetalGlb(settings.scene, metal, *settings.whiteMetalRoughness);
        sceneOptions.scene = metal.string();
    }
    if (settings.sky) sceneOptions.envColor = {settings.sky->x, settings.sky->y, settings.sky->z};
    if (!settings.environmentMap.empty()) {
        sceneOptions.env = settings.environmentMap.string();
        sceneOptions.envRotate = settings.environmentRotation;
    }
    const LoadedScene loaded = sceneOptions.loadScene();
    const MeshData& mesh = loaded.scene.mesh();
    if (const std::string why = unsupported(mesh, settings.sky || !settings.environmentMap.empty()); !why.empty()) {
        return {title + "Skipped: the script cannot give Cycles this scene as Strata sees it: " + why + ".\n", {}};
    }
    // The script gives Cycles a pinhole.
    if (loaded.settings.pose.apertureRadius > 0.0f) {
        return {title + "Skipped: the script cannot give Cycles this scene as Strata sees it: its camera has a lens.\n", {}};
    }
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    const Camera camera(loaded.settings.pose, settings.width, settings.height);
    const auto log = out / "vs-cycles.log";
    std::vector<int> cyclesSpp;
    for (int spp : settings.cyclesSpp) cyclesSpp.push_back(nearestPassMultiple(spp));
    const int largestSpp = *std::max_element(cyclesSpp.begin(), cyclesSpp.end());

    // One converged reference for every image: Strata's, with next-event estimation (the key
    // holds the depth and the NEE flag, not the sampler; every unbiased sampler converges to it).
    RenderOptions reference = sceneOptions;
    reference.depth = settings.depth;
    reference.nee = true;
    reference.threads = threads;
    ConvergenceSettings referenceSettings;
    referenceSettings.referencePasses = static_cast<uint32_t>(kReferenceSppFactor * largestSpp / kPathsPerPass);
    referenceSettings.makeReference = true;
    referenceSettings.seed = settings.seed;
    referenceSettings.outDir = out;
    const auto referenceFile = referencePath(out / "references", loaded, camera,
                                             reference.renderSettings(loaded.scene).integrator);
    const auto found = findReference(loaded, camera, reference, referenceSettings);
    if (!found || found->constant) return {title + "Skipped: no reference image.\n", {}};
    const glm::dvec3 referenceMeans = channelMeans(found->image);

    const auto script = out / "cycles_render.py";
    writeFile(script, std::string(cyclesScript()));
    const auto colourTextures = writeColourTextures(mesh, out / "textures");
    // An OBJ goes to Blender as it is; any other format as the triangles Strata loaded.
    fs::path blenderModel = sceneOptions.scene;
    std::string extension = blenderModel.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".obj") {
        blenderModel = out / (blenderModel.stem().string() + "-for-blender.obj");
        writeMeshObj(mesh, blenderModel);
    }
    std::vector<CyclesRun> cycles;
    for (int spp : cyclesSpp) {
        CyclesJob job;
        job.model = blenderModel;
        job.scale = cyclesUnitScale(mesh);
        job.materials = mesh.materials;
        job.colourTextures = colourTextures;
        job.sky = settings.sky.value_or(glm::vec3(0.0f));
        job.environmentMap = settings.environmentMap;
        job.environmentFrame = cyclesEnvironmentFrame(settings.environmentRotation);
        job.pose = camera.pose();
        job.width = settings.width;
        job.height = settings.height;
        job.spp = spp;
        job.maxBounces = cyclesMaxBounces(settings.depth);
        job.threads = threads;
        job.seed = settings.seed;
        job.out = out / ("vs-cycles-cycles-" + std::to_string(spp) + ".exr");
        const auto parameters = out / ("vs-cycles-cycles-" + std::to_string(spp) + ".json");
        writeFile(parameters, cyclesParameters(job));
        auto seconds = std::make_shared<std::vector<double>>();
        const auto readSeconds = [seconds](const fs::path& runLog) {
            std::ifstream in(runLog);
            std::stringstream text;
            text << in.rdbuf();
            const auto parsed = parseCyclesSeconds(text.str());
            if (parsed) seconds->push_back(*parsed);
            return parsed.has_value();
        };
        cycles.push_back({spp, job.out, seconds,
                          {"blender (Cycles, " + std::to_string(spp) + " spp)",
                           cyclesCommandLine(script, parameters), readSeconds, {}, {}}});
    }

    // The defaults; each of their levers turned off alone (what it gains is its row against the
    // defaults'), the warp of the strata onto the cosine measure too (strata24-cosine-qmc is the
    // same strata and points unwarped); roulette from bounce 2, the setting that trades the most
    // variance for time; and plain BSDF sampling with it.
    // On the real scenes: the defaults, plain BSDF sampling, and without next-event estimation
    // where it samples something (under a uniform sky it draws no shadow ray: the same paths).
    std::vector<StrataConfig> configs = {{defaultsLabel(), {}}};
    configs.push_back({"Strata defaults --no-nee", {}});
    configs.back().options.nee = false;
    if (settings.levers == CyclesLevers::All) {
        configs.push_back({"Strata defaults --roulette-depth -1", {}});
        configs.back().options.rouletteDepth = -1;
    }
    configs.push_back({"Strata defaults --sampler bsdf (no strata)", {}});
    configs.back().options.sampler = "bsdf";
    if (settings.levers == CyclesLevers::All) {
        configs.push_back({"Strata defaults --sampler strata24-cosine-qmc (strata not warped)", {}});
        configs.back().options.sampler = "strata24-cosine-qmc";
        configs.push_back({"Strata --roulette-depth 2", {}});
        configs.back().options.rouletteDepth = 2;
        configs.push_back({"Strata --sampler bsdf --roulette-depth 2", {}});
        configs.back().options.sampler = "bsdf";
        configs.back().options.rouletteDepth = 2;
    } else if (settings.sky) {
        configs.erase(configs.begin() + 1);
    }
    for (StrataConfig& config : configs) {
        config.options.scene = sceneOptions.scene;
        config.options.envColor = sceneOptions.envColor;
        config.options.env = sceneOptions.env;
        config.options.envRotate = sceneOptions.envRotate;
        config.options.width = settings.width;
        config.options.height = settings.height;
        config.options.depth = settings.depth;
        config.options.threads = threads;
        config.options.seed = settings.seed;
    }
    const auto strataRun = [&](size_t config, int cycles, int spp, const std::string& match) {
        const auto image = out / ("vs-cycles-strata-" + std::to_string(config) + "-" + std::to_string(spp) + ".exr");
        return StrataRun{config, cycles, spp, match, image,
                         {configs[config].label + ", " + std::to_string(spp) + " spp",
                          renderCommandLine(configs[config].options, spp, image), {}, {}, {}}};
    };
    // Races the Cycles renders with `strata`, alternated; the Cycles times pool over races.
    const auto raceWithCycles = [&](std::vector<StrataRun>& runs, const std::string& label) {
        std::vector<Entrant> entrants;
        for (const CyclesRun& c : cycles) entrants.push_back(c.entrant);
        for (const StrataRun& s : runs) entrants.push_back(s.entrant);
        const auto failed = race(entrants, settings.repeats, log, label);
        for (size_t i = 0; i < runs.size(); ++i) runs[i].entrant = entrants[cycles.size() + i];
        return failed;
    };
    const auto failure = [&](const std::string& name) {
        return CyclesComparison{title + "Skipped: `" + name + "` failed (see " + log.string() + ").\n", {}};
    };

    // First the same spp as Cycles, which also measures each configuration's start-up and cost
    // per sample; then the spp that takes as long as Cycles' render.
    std::vector<StrataRun> strata;
    for (size_t k = 0; k < configs.size(); ++k) {
        for (int spp : cyclesSpp) strata.push_back(strataRun(k, spp, spp, "same spp"));
    }
    if (const auto failed = raceWithCycles(strata, "vs-cycles, same spp")) return failure(*failed);
    std::vector<StrataRun> equalTime, reused;
    for (size_t k = 0; k < configs.size(); ++k) {
        std::vector<const StrataRun*> measuredRuns;
        for (const StrataRun& s : strata) {
            if (s.config == k) measuredRuns.push_back(&s);
        }
        const TimedSpp a{measuredRuns.front()->spp, measuredRuns.front()->entrant.medianWall()};
        const TimedSpp b{measuredRuns.back()->spp, measuredRuns.back()->entrant.medianWall()};
        for (const CyclesRun& c : cycles) {
            const int spp = equalTimeSpp(a, b, median(*c.renderSeconds), kPathsPerPass);
            const auto same = std::find_if(strata.begin(), strata.end(),
                                           [&](const StrataRun& s) { return s.config == k && s.spp == spp; });
            if (same == strata.end()) {
                equalTime.push_back(strataRun(k, c.spp, spp, "equal time"));
            } else if (same->cyclesSpp == c.spp) {
                same->match = "same spp, equal time";
            } else {  // the same-spp run of another Cycles budget: its image and times again
                reused.push_back(*same);
                reused.back().cyclesSpp = c.spp;
                reused.back().match = "equal time";
            }
        }
    }
    if (!equalTime.empty()) {
        if (const auto failed = raceWithCycles(equalTime, "vs-cycles, equal time")) return failure(*failed);
    }
    strata.insert(strata.end(), equalTime.begin(), equalTime.end());
    strata.insert(strata.end(), reused.begin(), reused.end());

    const auto measured = [&](const fs::path& image) {
        const Image rendered = readExr(image);
        return std::pair{measure(rendered, *found).relMse, channelMeans(rendered) / referenceMeans};
    };
    std::vector<CyclesRow> rows;
    std::vector<CyclesRatio> ratios;
    for (const CyclesRun& c : cycles) {
        const auto [relMse, means] = measured(c.image);
        const double cyclesCost = relMse * median(*c.renderSeconds);
        rows.push_back({kCyclesRenderer, "", c.spp, c.spp, relMse, median(*c.renderSeconds), means});
        CyclesRatio ratio{c.spp, 0.0, 0.0};
        for (size_t k = 0; k < configs.size(); ++k) {
            for (const StrataRun& s : strata) {
                if (s.config != k || s.cyclesSpp != c.spp) continue;
                const auto [strataRelMse, strataMeans] = measured(s.image);
                rows.push_back({configs[k].label, s.match, c.spp, s.spp, strataRelMse, s.entrant.medianWall(),
                                strataMeans});
                if (k != 0) continue;
                const double cost = strataRelMse * s.entrant.medianWall() / cyclesCost;
                if (s.match.find("same spp") != std::string::npos) ratio.sameSpp = cost;
                if (s.match.find("equal time") != std::string::npos) ratio.equalTime = cost;
            }
        }
        ratios.push_back(ratio);
    }

    const Table table = cyclesComparisonTable(rows);
    writeFile(out / "vs-cycles.csv", table.csv());
    std::vector<PlotSeries> series;
    for (const auto& [renderer, csv] : cyclesPlotData(rows)) {
        const std::string file = "vs-cycles-series-" + std::to_string(series.size()) + ".csv";
        writeFile(out / file, csv);
        series.push_back({renderer, file});
    }
    const std::string plotTitle = sceneName(settings.scene) + lightingText(settings) +
                                  cell(", %dx%d, depth %d, ", settings.width, settings.height, settings.depth) +
                                  threadsText(threads);
    runGnuplot(out, "vs-cycles", cyclesPlotScript(series, "vs-cycles.png", plotTitle));
    return {title +
           cell("%dx%d, depth %d (Cycles max_bounces %d), %s, medians of %d alternated runs. Seconds: "
                "`strata render` as a whole process (start-up, loading, BVH build, render, writing); "
                "Cycles' `bpy.ops.render.render()` alone, timed inside Blender (its start-up, scene "
                "building and image writing excluded). relMSE against one reference (%s, %d spp, "
                "%s), less the reference's own relMSE, %.3g, estimated from its two independent "
                "halves; the last column is each image's channel means over the reference's.\n\n",
                settings.width, settings.height, settings.depth, cyclesMaxBounces(settings.depth),
                threadsText(threads).c_str(), settings.repeats,
                found->kind == "cache" ? "cached Strata render" : "Strata render made now",
                kReferenceSppFactor * largestSpp, referenceFile.filename().string().c_str(), found->own.relMse) +
           table.markdown() +
           "\nRatios below 1 favour Strata; relMSE x s is the cost of a given error (Monte Carlo's "
           "relMSE falls as 1/time), so its ratio is the one to read. Equal-time spp come from the "
           "line through each configuration's two same-spp times. Cycles' settings: no adaptive "
           "sampling, denoising, clamping, glossy blur or light threshold, one bounce cap for every "
           "kind, a 1-pixel box filter, one-sided emission, the OBJ's vertex normals, the scene "
           "scaled to unit size; textures decoded by Strata into linear EXRs, bilinear and repeating; "
           "a map looked up through the rotation to Strata's convention, texels constant "
           "(script: " + script.string() + "; plot: " + (out / "vs-cycles.png").string() + ").\n",
            ratios};
}

}  // namespace strata
