#pragma once
// What both runtimes' ocean simulations (runtime/ocean_simulation.h on GL,
// runtime/vk_ocean_simulation.h on Vulkan) keep alike, over their own cascade and foam
// classes: the manifest's oceans built cascade by cascade with only the maps a shader reads,
// the time the maps hold (a step to that time again runs nothing), the foam's history, and
// the checks of a shader's map reference.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "codegen/shader_plan.h"
#include "runtime/ocean_gpu_foam.h"  // FoamHistory
#include "runtime/ocean_manifest.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

template <class Cascade, class Foam>
class OceanCascadeSet {
 public:
  struct Ocean {
    double choppiness = 0;
    std::vector<std::unique_ptr<Cascade>> cascades;
    std::vector<std::unique_ptr<Foam>> foam;  // per cascade, null where no shader reads it
  };

  // makeCascade(settings, ocean, cascade, slopesRead, foamRead, filtered) and makeFoam(settings,
  // cascade) build one cascade and its foam (on that cascade's own grid). A manifest whose ocean options do not parse is a manifest error.
  template <class MakeCascade, class MakeFoam>
  OceanCascadeSet(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                  MakeCascade makeCascade, MakeFoam makeFoam) {
    for (const OceanInfo& info : oceans) {
      const ocean::OceanSettings settings = manifestOceanSettings(info);
      Ocean o;
      o.choppiness = settings.cascades.choppiness;
      const int index = static_cast<int>(oceans_.size());
      for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
        const bool foam = oceanFoamRead(textures, settings, index, c, info.nodeId);
        // A filtered ocean (the compiler's OceanInfo::filtered: a shader reads its moments maps)
        // keeps every cascade's pyramids.
        o.cascades.push_back(makeCascade(settings, index, c, oceanMapRead(textures, index, c, ocean::kSlopeMap), foam,
                                         info.filtered));
        o.foam.push_back(foam ? makeFoam(settings, c) : nullptr);
      }
      oceans_.push_back(std::move(o));
    }
  }

  // step(foam or null, cascade, choppiness, history) for every cascade, unless the maps hold
  // `time` with the current history already (equal times only: a NaN never equals itself).
  // Whether it ran.
  template <class Step>
  bool advance(double time, Step step) {
    lastRan_ = !(heldAt_ && heldAt_->first == time && heldAt_->second == foamHistory_);
    if (!lastRan_) return false;
    heldAt_.reset();  // a throw below leaves no claim on the maps
    ++runs_;
    for (auto& o : oceans_)
      for (size_t c = 0; c < o.cascades.size(); ++c) step(o.foam[c].get(), *o.cascades[c], o.choppiness, foamHistory_);
    heldAt_.emplace(time, foamHistory_);
    return true;
  }

  void setFoamHistory(FoamHistory history) { foamHistory_ = history; }
  // After the GPU work of an advance failed: the maps hold no known time.
  void forgetHeldTime() { heldAt_.reset(); }
  // The foam steps the last advance ran, over every cascade (0 when it found the maps at its time).
  int lastFoamSteps() const {
    int steps = 0;
    if (!lastRan_) return steps;
    for (const auto& o : oceans_)
      for (const auto& f : o.foam)
        if (f) steps += f->lastSteps();
    return steps;
  }
  long runs() const { return runs_; }
  bool computesFoam(int ocean, int cascade) const {
    return oceans_.at(static_cast<size_t>(ocean)).foam.at(static_cast<size_t>(cascade)) != nullptr;
  }
  bool computesSlopes(int ocean, int cascade) const {
    return oceans_.at(static_cast<size_t>(ocean)).cascades.at(static_cast<size_t>(cascade))->computesSlopes();
  }

  // The cascade a shader's map reference reads, and its foam when the map is the foam: a
  // manifest error when it names no ocean, or a map the simulation was not asked to compute.
  // (The pointers are not const: the Vulkan runtime transitions the images it binds.)
  std::pair<Cascade*, Foam*> mapSource(const OceanMapRef& ref) const {
    std::vector<size_t> cascades;
    for (const Ocean& o : oceans_) cascades.push_back(o.cascades.size());
    checkOceanMapRef(ref, cascades);
    const Ocean& o = oceans_[static_cast<size_t>(ref.ocean)];
    Cascade& c = *o.cascades[static_cast<size_t>(ref.cascade)];
    const std::string which = "ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade);
    if (ref.map == ocean::kSlopeMap && !c.computesSlopes())
      manifestError("an ocean texture reads the slope map of " + which + ", which the simulation was not asked to compute");
    if (ref.map == ocean::kMomentsMap && !c.filtered())
      manifestError("an ocean texture reads the moments map of " + which + ", which the simulation was not asked to compute");
    if (ref.map != ocean::kFoamMap) return {&c, nullptr};
    if (!computesFoam(ref.ocean, ref.cascade))
      manifestError("an ocean texture reads the foam of " + which + ", which the simulation was not asked to compute");
    return {&c, o.foam[static_cast<size_t>(ref.cascade)].get()};
  }

 private:
  std::vector<Ocean> oceans_;
  FoamHistory foamHistory_ = FoamHistory::Replay;
  // The time and foam history the maps hold, once advanced; whether the last advance ran.
  std::optional<std::pair<double, FoamHistory>> heldAt_;
  bool lastRan_ = false;
  long runs_ = 0;
};

}  // namespace wg::rt
