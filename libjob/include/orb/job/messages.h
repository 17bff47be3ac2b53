// What the render job has to say besides progress (a warning, a note) goes
// to the caller through a sink: the library never prints. orb-render's sink
// prints them as its other messages (orb::cli::warning, orb::cli::info).
#pragma once

#include <functional>
#include <string>

namespace orb::job {

enum class MessageKind { Info, Warning, Error };

// None: the messages are dropped.
using MessageSink = std::function<void(MessageKind, const std::string&)>;

inline void say(const MessageSink& sink, MessageKind kind, const std::string& message) {
    if (sink) sink(kind, message);
}

}  // namespace orb::job
