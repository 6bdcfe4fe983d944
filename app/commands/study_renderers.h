// The scenes of a protocol and one renderer per (scene, alternative), made before the first trial
// so that no trial waits for one; each scene's geometry, chunk table and shadow map are uploaded
// once and shared by its alternatives' renderers (modes::SceneResources).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "app/commands/study_scenes.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/scene.h"
#include "study/protocol.h"
#include "study/render_mode.h"

namespace monoplane::app {

// The renderer's mode and stereo pass for a protocol's mode name (stereo-multiview, stereo-gs and
// stereo-instanced are stereo drawn in one pass).
plan::RenderModeChoice renderer_mode(study::RenderMode mode);

// The chooser's parameters of a protocol's [auto] table (hybrid-auto alternatives).
plan::AutoMonoPlaneParams auto_mono_plane_params(const study::AutoPlaneSettings& settings);

// The scenes and a renderer per (scene, mode) of the protocol, made before the first trial so
// that no trial waits for one.
class StudyRenderers {
  public:
    // The protocol's scenes, rendered with its [render] settings into eyes of `extent`; C's
    // target sized once for the protocol's nearest m. Built-in scenes are generated at the
    // session's detail; scenes that name glTF files are taken from `imported` (loaded and
    // digested before the session began): one missing there is a UserError.
    StudyRenderers(const vk_core::Context& ctx, const study::Protocol& protocol,
                   vk::Extent2D extent, const study::RenderSettings& render,
                   ImportedStudyScenes imported);
    modes::ModeRenderer& renderer(const std::string& scene, study::RenderMode mode) {
        return *renderers_.at({scene, mode});
    }
    // Every renderer, e.g. to finish their frames in flight at the end of a session.
    template <class F>
    void for_each(F f) {
        for (auto& [key, renderer] : renderers_) f(*renderer);
    }
    // The protocol's scenes by name, for what looks into them besides the renderers (the gaze
    // points, gaze_point.h); they live as long as this object.
    std::map<std::string, const scenes::Scene*> scenes() const {
        std::map<std::string, const scenes::Scene*> all;
        for (const auto& [name, scene] : scenes_) all[name] = scene.get();
        return all;
    }
    const rig::Pose& seat(const std::string& scene) const {
        const scenes::Viewpoint* v = scenes_.at(scene)->find_viewpoint("default");
        return v->head;
    }

  private:
    std::map<std::string, std::unique_ptr<scenes::Scene>> scenes_;  // outlive the renderers
    std::map<std::pair<std::string, study::RenderMode>, std::unique_ptr<modes::ModeRenderer>>
        renderers_;
};

}  // namespace monoplane::app
