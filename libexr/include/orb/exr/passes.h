// The layers ("passes") orb-render can write, their EXR channel names, and
// the comma-separated form users type (--passes beauty,albedo). All of it
// comes from the film's channel table (ORB_FILM_LAYERS and ORB_FILM_CHANNELS
// in libtables/include/orb/tables/film_channels.h).
#pragma once

#include <string>
#include <vector>

#include "orb/tables/film_channels.h"

namespace orb::exr {

// Beauty, Direct, Indirect, Emission, Albedo, Normal, Depth, Variance, Id.
using Pass = film::Layer;

// Every pass, in the order they are documented and written.
const std::vector<Pass>& all_passes();

// What "all" means (--passes all, ExrWriteOptions' default): every pass but
// `samples`, whose per-pixel counts only adaptive sampling makes differ from
// orb:spp; it is written with --noise-threshold or when named.
const std::vector<Pass>& image_passes();

const char* pass_name(Pass pass);  // "beauty", "direct", ...

// Channels a pass writes, e.g. Beauty -> R,G,B,A; Normal -> N.X,N.Y,N.Z.
std::vector<std::string> pass_channels(Pass pass);

// Helper channels written next to a pass so that --resume recovers the film's
// sums exactly (Normal -> orb.normalLength). Always FLOAT.
std::vector<std::string> pass_resume_channels(Pass pass);

// The film channels stored in a pass, in table order.
std::vector<const film::ChannelInfo*> pass_film_channels(Pass pass);

// The UINT channels that carry a Sum channel's exact sums in a file that
// may be continued or merged (docs/orb-render.md, "Exact sums"): component
// `component`'s 64-bit sum as its low and high 32 bits,
// "orb.sum.<its channel name>.lo" and ".hi" (orb.sum.R.lo, orb.sum.R.hi).
std::string exact_sum_channel_name(const film::ChannelInfo& channel, int component, bool high);

// Those of every Sum channel of a pass (none for depth or id).
std::vector<std::string> pass_exact_sum_channels(Pass pass);

// Parses "beauty,albedo" (or "all": image_passes()); duplicates are dropped, the result is in
// all_passes() order. Throws std::invalid_argument naming the bad entry.
std::vector<Pass> parse_passes(const std::string& list);

std::string format_passes(const std::vector<Pass>& passes);  // "beauty,albedo"

bool contains(const std::vector<Pass>& passes, Pass pass);

}  // namespace orb::exr
