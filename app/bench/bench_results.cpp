#include "app/bench/bench_results.h"

#include <map>
#include <set>
#include <sstream>

#include "common/json_writer.h"
#include "renderer/plan/frame_plan_json.h"

namespace monoplane::app {

namespace {

// A run's stereo reference: two-pass stereo of its scene at its level of detail.
std::string stereo_key(const BenchRun& run) {
    return run.scene + "\n" + run.lod;
}

// The same configuration at another level of detail.
bool same_but_lod(const BenchRun& a, const BenchRun& b) {
    return a.scene == b.scene && a.mode == b.mode && a.variant == b.variant &&
           a.stereo_pass == b.stereo_pass && a.mono_plane_auto == b.mono_plane_auto &&
           a.mono_plane_is_far == b.mono_plane_is_far &&
           (a.mono_plane_auto || a.mono_plane == b.mono_plane);
}

// An auto run's median over the matching off run's, where the bench did not pair them itself.
void add_lod_ratios(BenchReport& report) {
    for (BenchRun& run : report.runs) {
        if (run.lod != "auto" || run.time_ratio_vs_lod_off) continue;
        for (const BenchRun& off : report.runs) {
            if (off.lod == "off" && same_but_lod(run, off) && off.frame_ms_median > 0.0) {
                run.time_ratio_vs_lod_off = run.frame_ms_median / off.frame_ms_median;
                break;
            }
        }
    }
}

}  // namespace

void add_ratios_to_stereo(BenchReport& report) {
    add_lod_ratios(report);
    std::map<std::string, const BenchRun*> stereo;
    for (const BenchRun& run : report.runs) {
        if (run.mode == "stereo") stereo[stereo_key(run)] = &run;
    }
    for (BenchRun& run : report.runs) {
        const auto found = stereo.find(stereo_key(run));
        if (found == stereo.end()) continue;
        const BenchRun& reference = *found->second;
        if (&run == &reference) run.time_ratio = 1.0;
        if (!run.time_ratio && reference.frame_ms_median > 0.0) {
            run.time_ratio = run.frame_ms_median / reference.frame_ms_median;
        }
        if (reference.primitives > 0) {
            run.primitive_ratio =
                static_cast<double>(run.primitives) / static_cast<double>(reference.primitives);
        }
        if (reference.vertex_invocations > 0) {
            run.vertex_invocation_ratio = static_cast<double>(run.vertex_invocations) /
                                          static_cast<double>(reference.vertex_invocations);
        }
    }
}

namespace {

bool same_configuration(const BenchRun& fixed, const BenchRun& automatic) {
    return !fixed.mono_plane_auto && fixed.mono_plane && fixed.scene == automatic.scene &&
           fixed.lod == automatic.lod && fixed.mode == automatic.mode &&
           fixed.variant == automatic.variant && fixed.time_ratio && fixed.visible_error_arcmin;
}

std::string fixed_name(const BenchRun& fixed) {
    std::ostringstream name;
    name << "m=";
    if (fixed.mono_plane_is_far) {
        name << "far";
    } else {
        name << *fixed.mono_plane;
    }
    return name.str();
}

}  // namespace

void mark_auto_frontier(BenchReport& report) {
    for (BenchRun& automatic : report.runs) {
        if (!automatic.mono_plane_auto || !automatic.time_ratio ||
            !automatic.visible_error_arcmin) {
            continue;
        }
        automatic.dominated_by.clear();
        automatic.dominated_beyond_spread_by.clear();
        for (const BenchRun& fixed : report.runs) {
            if (!same_configuration(fixed, automatic)) continue;
            if (!(*fixed.visible_error_arcmin < *automatic.visible_error_arcmin)) continue;
            if (*fixed.time_ratio < *automatic.time_ratio) {
                automatic.dominated_by.push_back(fixed_name(fixed));
            }
            if (fixed.time_ratio_p75 && automatic.time_ratio_p25 &&
                *fixed.time_ratio_p75 < *automatic.time_ratio_p25) {
                automatic.dominated_beyond_spread_by.push_back(fixed_name(fixed));
            }
        }
        automatic.on_fixed_m_frontier = automatic.dominated_by.empty();
    }
}

namespace {

void optional_value(JsonWriter& j, std::string_view key, const std::optional<double>& value) {
    if (value) {
        j.value(key, *value);
    } else {
        j.null(key);
    }
}

// The turning-head configuration's keys (bench --turning-frames).
void write_turning(JsonWriter& j, const BenchRun& run) {
    j.value("turning_frames", static_cast<std::uint64_t>(run.turning_frames));
    optional_value(j, "turning_time_ratio", run.turning_time_ratio);
    if (run.turning_driver_compiles) {
        j.value("turning_driver_compiles", *run.turning_driver_compiles);
    } else {
        j.null("turning_driver_compiles");
    }
    optional_value(j, "turning_compile_share", run.turning_compile_share);
}

// An auto run's keys: the range of m it chose, and whether a fixed m beat it (mark_auto_frontier).
void write_auto_plane(JsonWriter& j, const BenchRun& run) {
    optional_value(j, "mono_plane_min", run.mono_plane_min);
    optional_value(j, "mono_plane_max", run.mono_plane_max);
    j.value("stereo_frames", run.stereo_frames);
    if (run.on_fixed_m_frontier) j.value("on_fixed_m_frontier", *run.on_fixed_m_frontier);
    j.begin_array("dominated_by");
    for (const std::string& other : run.dominated_by) j.value(std::string_view(), other);
    j.end_array();
    j.begin_array("dominated_beyond_spread_by");
    for (const std::string& other : run.dominated_beyond_spread_by) {
        j.value(std::string_view(), other);
    }
    j.end_array();
}

template <typename Value>
void write_map(JsonWriter& j, std::string_view key, const std::map<std::string, Value>& values) {
    j.begin_object(key);
    for (const auto& [name, value] : values) j.value(name, value);
    j.end_object();
}

// Times per frame and per pass, and the pipeline statistics' counts per view.
void write_times_and_counts(JsonWriter& j, const BenchRun& run) {
    j.value("frame_ms_median", run.frame_ms_median).value("frame_ms_p90", run.frame_ms_p90);
    j.value("frame_ms_p10", run.frame_ms_p10).value("cpu_ms_median", run.cpu_ms_median);
    write_map(j, "passes", run.pass_ms_median);
    write_map(j, "passes_p10", run.pass_ms_p10);
    write_map(j, "passes_p90", run.pass_ms_p90);
    j.value("primitives", run.primitives).value("fragments", run.fragments);
    j.value("vertex_invocations", run.vertex_invocations);
    j.value("geometry_invocations", run.geometry_invocations);
    write_map(j, "view_primitives", run.view_primitives);
    write_map(j, "view_fragments", run.view_fragments);
    write_map(j, "view_fragments_per_pixel", run.view_fragments_per_pixel);
    write_map(j, "draws", run.view_draws);
}

// Accuracy against the stereo reference, and the ratios to its time and counts.
void write_comparison_with_stereo(JsonWriter& j, const BenchRun& run) {
    optional_value(j, "ssim_vs_stereo", run.ssim_vs_stereo);
    optional_value(j, "mean_abs_difference_vs_stereo", run.mean_abs_difference);
    optional_value(j, "max_error_px", run.max_error_px);
    optional_value(j, "max_error_arcmin", run.max_error_arcmin);
    optional_value(j, "visible_error_arcmin", run.visible_error_arcmin);
    optional_value(j, "drift_px", run.drift_px);
    j.value("drift_patches", static_cast<std::uint64_t>(run.drift_patches));
    optional_value(j, "time_ratio_vs_stereo", run.time_ratio);
    optional_value(j, "stereo_frame_ms_median", run.stereo_frame_ms_median);
    optional_value(j, "time_ratio_p25", run.time_ratio_p25);
    optional_value(j, "time_ratio_p75", run.time_ratio_p75);
    optional_value(j, "primitive_ratio_vs_stereo", run.primitive_ratio);
    optional_value(j, "vertex_invocation_ratio_vs_stereo", run.vertex_invocation_ratio);
    optional_value(j, "time_ratio_vs_lod_off", run.time_ratio_vs_lod_off);
}

void write_run(JsonWriter& j, const BenchRun& run) {
    j.begin_object();
    j.value("scene", run.scene).value("mode", run.mode).value("variant", run.variant);
    if (!run.variant_chosen.empty()) j.value("variant_chosen", run.variant_chosen);
    j.value("stereo_pass", run.stereo_pass);
    j.value("lod", run.lod).value("lod_error_px", run.lod_error_px);
    optional_value(j, "mono_plane", run.mono_plane);
    j.value("mono_plane_is_far", run.mono_plane_is_far);
    j.value("mono_plane_auto", run.mono_plane_auto);
    if (run.mono_plane_auto) write_auto_plane(j, run);
    write_times_and_counts(j, run);
    write_device_memory_json(j, run.device_memory);
    plan::write_plan_json(j, run.plan);
    write_comparison_with_stereo(j, run);
    if (run.turning_frames > 0) write_turning(j, run);
    if (run.max_channel_difference) {
        j.value("max_channel_difference_vs_stereo", *run.max_channel_difference);
    } else {
        j.null("max_channel_difference_vs_stereo");
    }
    j.end_object();
}

}  // namespace

std::string bench_json(const BenchReport& report) {
    JsonWriter j;
    j.begin_object();
    j.value("device", report.device).value("hmd", report.hmd);
    j.value("width", report.width).value("height", report.height);
    j.value("detail", report.detail).value("view", report.view).value("seed", report.seed);
    j.value("anti_aliasing", report.anti_aliasing).value("ssao", report.ssao);
    j.value("vertex_work", static_cast<std::uint64_t>(report.vertex_work));
    j.value("depth_prepass", report.depth_prepass);
    j.value("warmup_frames", report.warmup).value("frames", report.frames);
    j.begin_array("runs");
    for (const BenchRun& run : report.runs) write_run(j, run);
    j.end_array();
    j.end_object();
    return j.str();
}

namespace {

std::string number(const std::optional<double>& value) {
    if (!value) return "";
    std::ostringstream text;
    text.precision(10);
    text << *value;
    return text.str();
}

}  // namespace

std::string bench_csv(const BenchReport& report) {
    std::set<std::string> pass_names;
    for (const BenchRun& run : report.runs) {
        for (const auto& [name, ms] : run.pass_ms_median) pass_names.insert(name);
    }
    std::ostringstream csv;
    csv << "scene,mode,variant,mono_plane,mono_plane_is_far,frame_ms_median,frame_ms_p10,"
           "frame_ms_p90,cpu_ms_median,primitives,fragments,primitives_left,primitives_right,"
           "primitives_mono,draws_left,draws_right,draws_mono,ssim_vs_stereo,max_error_px,"
           "drift_px,time_ratio_vs_stereo,primitive_ratio_vs_stereo,stereo_pass,"
           "vertex_invocations,geometry_invocations,vertex_invocation_ratio_vs_stereo,"
           "max_channel_difference_vs_stereo,mono_plane_auto,max_error_arcmin,"
           "visible_error_arcmin,turning_time_ratio,turning_driver_compiles,"
           "turning_compile_share,lod,lod_error_px,mean_abs_difference_vs_stereo,"
           "time_ratio_vs_lod_off";
    for (const std::string& name : pass_names) csv << ",pass_ms_" << name;
    csv << "\n";
    auto count = [](const std::map<std::string, std::uint64_t>& values, const char* key) {
        const auto found = values.find(key);
        return found == values.end() ? std::uint64_t{0} : found->second;
    };
    for (const BenchRun& run : report.runs) {
        csv << run.scene << "," << run.mode << "," << run.variant << "," << number(run.mono_plane)
            << "," << (run.mono_plane_is_far ? "TRUE" : "FALSE") << ","
            << number(run.frame_ms_median) << "," << number(run.frame_ms_p10) << ","
            << number(run.frame_ms_p90) << "," << number(run.cpu_ms_median) << "," << run.primitives
            << "," << run.fragments << "," << count(run.view_primitives, "left") << ","
            << count(run.view_primitives, "right") << "," << count(run.view_primitives, "mono")
            << "," << count(run.view_draws, "left") << "," << count(run.view_draws, "right") << ","
            << count(run.view_draws, "mono") << "," << number(run.ssim_vs_stereo) << ","
            << number(run.max_error_px) << "," << number(run.drift_px) << ","
            << number(run.time_ratio) << "," << number(run.primitive_ratio) << ","
            << run.stereo_pass << "," << run.vertex_invocations << "," << run.geometry_invocations
            << "," << number(run.vertex_invocation_ratio) << ","
            << (run.max_channel_difference ? std::to_string(*run.max_channel_difference) : "")
            << "," << (run.mono_plane_auto ? "TRUE" : "FALSE") << ","
            << number(run.max_error_arcmin) << "," << number(run.visible_error_arcmin) << ","
            << number(run.turning_time_ratio) << ","
            << (run.turning_driver_compiles ? std::to_string(*run.turning_driver_compiles) : "")
            << "," << number(run.turning_compile_share) << "," << run.lod << ","
            << number(run.lod_error_px) << "," << number(run.mean_abs_difference) << ","
            << number(run.time_ratio_vs_lod_off);
        for (const std::string& name : pass_names) {
            const auto found = run.pass_ms_median.find(name);
            csv << ",";
            if (found != run.pass_ms_median.end()) csv << number(found->second);
        }
        csv << "\n";
    }
    return csv.str();
}

}  // namespace monoplane::app
