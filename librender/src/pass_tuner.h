// Chooses how many samples per pixel a pass adds, from the passes timed so far,
// so that one pass takes about a target time on the device.
#pragma once

namespace orb::render {

class PassTuner {
public:
    // target_seconds: the pass length aimed at.
    explicit PassTuner(double target_seconds) : target_seconds_(target_seconds) {}

    void record(int samples, double seconds);
    int suggested() const;
    // Seconds per sample per pixel, smoothed over the passes timed; 0 before the first.
    double seconds_per_sample() const { return seconds_per_sample_; }

private:
    double target_seconds_;
    int passes_ = 0;
    int last_samples_ = 0;
    double seconds_per_sample_ = 0;  // per sample per pixel, smoothed
};

}  // namespace orb::render
