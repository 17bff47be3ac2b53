// Names of the orb:* header attributes, shared by the writer and the reader.
#pragma once

namespace orb::exr::attr {

inline constexpr const char* kFilmFormat = "orb:filmFormat";
inline constexpr const char* kSpp = "orb:spp";
inline constexpr const char* kSampleRanges = "orb:sampleRanges";
inline constexpr const char* kTargetSpp = "orb:targetSpp";
inline constexpr const char* kSeed = "orb:seed";
inline constexpr const char* kMaxDepth = "orb:maxDepth";
inline constexpr const char* kMode = "orb:mode";
inline constexpr const char* kSampler = "orb:sampler";
inline constexpr const char* kDevice = "orb:device";
inline constexpr const char* kRenderSeconds = "orb:renderSeconds";
inline constexpr const char* kSceneFile = "orb:sceneFile";
inline constexpr const char* kSceneHash = "orb:sceneHash";
inline constexpr const char* kSceneTime = "orb:sceneTime";
inline constexpr const char* kVersion = "orb:version";
inline constexpr const char* kPasses = "orb:passes";
inline constexpr const char* kEnvironmentSeen = "orb:environmentSeen";
inline constexpr const char* kFrame = "orb:frame";
inline constexpr const char* kFps = "orb:fps";
inline constexpr const char* kNoiseThreshold = "orb:noiseThreshold";
inline constexpr const char* kTargetError = "orb:targetError";
inline constexpr const char* kAdaptiveStop = "orb:adaptiveStop";
inline constexpr const char* kExactSums = "orb:exactSums";
inline constexpr const char* kKernel = "orb:kernel";

}  // namespace orb::exr::attr
