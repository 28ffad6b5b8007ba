#include "studies.hpp"

#include <cstdio>
#include <string>

namespace lumavel::host::reproduce {
namespace {

WorkSize working_for(int w, int h) {
  // The core's largest working width is 160: larger frames are binned to it.
  if (w > 160) return {160, 160 * h / w};
  return {w, h};
}

}  // namespace

std::vector<Study> paper_studies(bool quick) {
  std::vector<Study> out;

  Study sim{"Paper Section IV-B: simulated rig (Fig. 4b, 4c)",
            "16 s, 8 s straight then a 15 m radius circle, V from 0.5 to 0.6 m/s, h = 8 cm, "
            "rigs aligned and misaligned by 1.6 deg. Worst |V error| after the first second. "
            "Rendered at 160x120 by exact area averaging (the same pixels as 640x480 binned 4x4).",
            "worst", {}};
  const double sim_len = quick ? 4 : -1;
  sim.cases.push_back({"sim_aligned", "paper_sim_aligned.yaml", 160, 120, -1, sim_len,
                       {{160, 120}, {40, 30}}, "aligned (Fig. 4b)", 0.002, ""});
  sim.cases.push_back({"sim_misaligned", "paper_sim_misaligned.yaml", 160, 120, -1, sim_len,
                       {{160, 120}, {40, 30}}, "misaligned 1.6 deg (Fig. 4c)", 0.015, ""});
  out.push_back(sim);

  Study res{"Paper Table I: resolution",
            "Photo wall passed at 3.5 m/s (14 m in 4 s), exposure 0. Each row renders the camera "
            "at that resolution; lumavel works at it (frames wider than 160 are binned to 160 columns).",
            "E", {}};
  const std::vector<std::pair<WorkSize, double>> table1 = {
      {{640, 480}, 6.80}, {{320, 240}, 6.82}, {{160, 120}, 6.84}, {{80, 60}, 6.82}, {{40, 30}, 7.45}, {{20, 15}, 9.22}};
  for (const auto& [sz, paper] : table1) {
    if (quick && sz.width > 40) continue;
    res.cases.push_back({"wall_" + std::to_string(sz.width) + "x" + std::to_string(sz.height), "robustness_wall.yaml",
                         sz.width, sz.height, 0, -1, {working_for(sz.width, sz.height)},
                         std::to_string(sz.width) + "x" + std::to_string(sz.height), paper, ""});
  }
  out.push_back(res);

  Study blur{"Paper Table II: exposure (motion blur)",
             "The same wall with exposure times from 0 to 1.25 frame periods. Rendered at 160x120 "
             "(= 640x480 binned 4x4), run at 160x120 and at 40x30.",
             "E", {}};
  const std::vector<std::pair<double, double>> table2 = {{0, 6.80}, {0.25, 6.89}, {0.5, 6.88},
                                                         {0.75, 6.89}, {1.0, 6.91}, {1.25, 7.24}};
  for (const auto& [exposure, paper] : table2) {
    if (quick && exposure != 0 && exposure != 1.25) continue;
    char id[32];
    std::snprintf(id, sizeof id, "wall_exposure_%03d", static_cast<int>(exposure * 100 + 0.5));
    char label[32];
    std::snprintf(label, sizeof label, "%.2f", exposure);
    blur.cases.push_back({id, "robustness_wall.yaml", quick ? 40 : 160, quick ? 30 : 120, exposure, -1,
                          quick ? std::vector<WorkSize>{{40, 30}} : std::vector<WorkSize>{{160, 120}, {40, 30}}, label,
                          paper, ""});
  }
  out.push_back(blur);

  Study trolley{"Paper Section IV-C: trolley (Fig. 7)",
                "2 m track back and forth at 20.83 fps, clutter at 0.3 to 3.5 m, 50 Hz lighting aliased "
                "to 4.17 Hz, 1.57 deg misalignment. L1 error sum|err| / sum|V|. Rendered at 160x120.",
                "L1", {}};
  trolley.cases.push_back({"trolley", "paper_trolley.yaml", 160, 120, -1, quick ? 6.0 : -1.0,
                           {{160, 120}, {40, 30}}, "trolley", -1, ""});
  out.push_back(trolley);

  Study turning{"Turning with gyro noise and bias", "A turning run with a noisy, biased gyro.", "E", {}};
  turning.cases.push_back({"turning", "gyro_turning.yaml", -1, -1, -1, quick ? 4.0 : -1.0, {{40, 30}}, "turning", -1, ""});
  out.push_back(turning);

  Study texture{"Untextured scene, dark frames, dropped frames",
                "Status flags and behaviour where the images cannot show motion.", "flags", {}};
  texture.cases.push_back({"untextured", "untextured_then_textured.yaml", -1, -1, -1, -1, {{40, 30}}, "untextured then textured", -1, ""});
  texture.cases.push_back({"dark", "dark_frames.yaml", -1, -1, -1, -1, {{40, 30}}, "dark frames", -1, ""});
  texture.cases.push_back({"dropped", "dropped_frames.yaml", -1, -1, -1, -1, {{40, 30}}, "dropped frames", -1, ""});
  out.push_back(texture);
  out.push_back(real_rig_study(quick));
  return out;
}

Study real_rig_study(bool quick) {
  Study st{"Real rigs: near objects, a street, reversals, mismatched cameras",
           "h = 8 cm, 60 Hz, rendered at 160x120 and run at 40x30 (host_sim/scenarios/README.md describes each "
           "scene). Near clutter: boxes, poles, chairs and plants 0.3-1 m from the path before a room at 3-6 m, "
           "S-turns, 0.3-1 m/s. Street: 5-12 m/s past parked cars at 1.7-2.3 m, poles and trunks at 3-3.6 m, "
           "facades at 5-15 m. Back and forth: a trolley shuttling among clutter at 0.3-3 m with 4 reversals and "
           "standstills. All with gyro offset and noise, pixel noise, and flicker where lamps are. \"mismatched\": "
           "the two cameras are the `cheap_pair` preset (gain 1.00 vs 1.20, black level 10 vs 12, corner "
           "fall-off 30 vs 36 %, per-pixel and per-column fixed pattern). The photo wall of Table I (14 m in "
           "4 s at 4 m) runs with matched and with mismatched cameras, and with cameras that differ only in "
           "gain, black level and vignetting (`differing_pair`: gain 1.00 vs 0.85, black level 10 vs 12, corner "
           "fall-off 30 vs 36 %). The last rows go beyond what the photometric match models (no target; docs/design.md, "
           "\"Beyond the model\"): the wall with cameras whose tone curves differ (`tone_pair`: cam1 gamma 1.05, twins "
           "otherwise); the wide-lens slalom of the lens study with `differing_pair` cameras, a rig that never "
           "turns little enough for the match to learn; and the photo wall under 100 Hz lamp flicker of 15 % "
           "(`flicker_wall.yaml`, 60 Hz frames, exposure 0), with matched cameras and with the two presets that "
           "have black levels, over which the division by the brightness does not cancel the ripple; and the photo "
           "wall with cam1 misaligned by 1.6 deg (`misaligned_wall.yaml`, the misalignment in T_BS), more than the "
           "wall's stereo disparity; and a picket fence (`picket_fence.yaml`: 3 cm pickets every 10 cm at 1.0 m, then 4 cm every 14 cm at 0.9 m, a hedge and a house through the gaps), a texture that repeats within 2h and aliases the stereo difference (docs/design.md, \"The images' direction of travel\"); and the near-clutter pass from a rig that pitches, rolls and bounces as a trolley does (`vibrating_clutter.yaml`; docs/design.md, \"Vibration\"). Every run as `run` does it by default: the darker camera's frames clamped "
           "where the brighter one clips (docs/design.md, \"Clip match\"), the photometric match learning the rest.",
           "E", {}};
  const double len = quick ? 4 : -1;
  struct Scene {
    const char* id;
    const char* file;
    const char* label;
  };
  for (const Scene& sc : {Scene{"near_clutter", "near_clutter.yaml", "near clutter"},
                          Scene{"street_pass", "street_pass.yaml", "street pass"},
                          Scene{"back_and_forth", "back_and_forth.yaml", "back and forth"},
                          Scene{"wall", "robustness_wall.yaml", "photo wall"}}) {
    if (quick && std::string(sc.id) != "near_clutter") continue;
    for (bool mismatched : {false, true}) {
      st.cases.push_back({std::string(sc.id) + (mismatched ? "_mismatched" : "_matched"), sc.file, 160, 120, -1, len,
                          {{40, 30}}, std::string(sc.label) + (mismatched ? ", mismatched" : ""), -1,
                          mismatched ? "cheap_pair" : ""});
    }
  }
  if (quick) return st;
  st.cases.push_back({"wall_differing", "robustness_wall.yaml", 160, 120, -1, len, {{40, 30}},
                      "photo wall, gain, black level and vignetting differ", -1, "differing_pair"});
  // Beyond what the match models: another tone curve, and a rig that turns
  // all the time (the match learns only where it turns little).
  st.cases.push_back({"wall_tone", "robustness_wall.yaml", 160, 120, -1, len, {{40, 30}},
                      "photo wall, tone curves differ (`tone_pair`)", -1, "tone_pair"});
  st.cases.push_back({"lens_slalom_differing", "wide_lens_slalom.yaml", -1, -1, -1, len, {{40, 30}},
                      "wide-lens slalom (hfov 90, +-1 rad/s), `differing_pair`", -1, "differing_pair"});
  // A misalignment of the wall's own disparity (a row of the unusual
  // recordings: the columns' elevation reach differs between the cameras).
  st.cases.push_back({"wall_misaligned", "misaligned_wall.yaml", -1, -1, -1, len, {{40, 30}},
                      "photo wall, cam1 misaligned 1.6 deg (in sensor.yaml)", -1, ""});
  // A texture that repeats within 2h (picket fences): where the stereo
  // difference aliases and the kernels do not resolve the pickets.
  st.cases.push_back({"picket_fence", "picket_fence.yaml", -1, -1, -1, len, {{40, 30}},
                      "picket fence (10 and 14 cm pickets at 1.0 and 0.9 m)", -1, ""});
  // Near clutter from a rig that shakes as a trolley does: the column sums'
  // edge rows move with every tilt, which the yaw gyro does not say.
  st.cases.push_back({"vibrating_clutter", "vibrating_clutter.yaml", -1, -1, -1, len, {{40, 30}},
                      "near clutter on a shaking trolley (pitch 1, roll 0.5 deg, heave 3 mm rms, 2-15 Hz)", -1, ""});
  // Lamp flicker over the cameras' black levels (the division by N cancels a
  // common gain only): twins, then the two presets with black levels.
  for (const char* preset : {"", "differing_pair", "cheap_pair"}) {
    const std::string p = preset;
    st.cases.push_back({"wall_flicker" + (p.empty() ? std::string("_matched") : "_" + p), "flicker_wall.yaml", -1, -1,
                        -1, len, {{40, 30}},
                        "photo wall under 100 Hz flicker" + (p.empty() ? std::string() : ", `" + p + "`"), -1, p});
  }
  return st;
}

}  // namespace lumavel::host::reproduce
