#include "common/frame_clock/silence_watch.hpp"

#include <gtest/gtest.h>

namespace fedsim::timing {
namespace {

using Event = SilenceWatch::Event;

TEST(SilenceWatch, WriterOnEveryFrameIsNeverSilent) {
  SilenceWatch watch(10);
  for (std::uint64_t f = 1; f <= 1000; ++f) EXPECT_EQ(watch.observe(f, true, true), Event::kNone);
  EXPECT_FALSE(watch.silent());
}

TEST(SilenceWatch, ReportsOnceAfterTheLimitAndOnceWhenTheWriterResumes) {
  SilenceWatch watch(10);
  EXPECT_EQ(watch.observe(1, true, true), Event::kNone);
  std::vector<std::uint64_t> silent_at;
  for (std::uint64_t f = 2; f <= 40; ++f) {
    if (watch.observe(f, true, false) == Event::kSilent) silent_at.push_back(f);
  }
  ASSERT_EQ(silent_at, std::vector<std::uint64_t>{11});  // 10 frames after the last sample
  EXPECT_TRUE(watch.silent());
  EXPECT_EQ(watch.quiet_frames(), 39u);
  EXPECT_EQ(watch.observe(41, true, true), Event::kResumed);
  EXPECT_FALSE(watch.silent());
  EXPECT_EQ(watch.observe(42, true, true), Event::kNone);
}

TEST(SilenceWatch, GapsShorterThanTheLimitAreNotReported) {
  SilenceWatch watch(10);
  std::uint64_t f = 1;
  for (int gap = 0; gap < 50; ++gap) {
    EXPECT_EQ(watch.observe(f++, true, true), Event::kNone);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(watch.observe(f++, true, false), Event::kNone);
  }
  // Negative control: one frame more of silence is reported.
  EXPECT_EQ(watch.observe(f++, true, true), Event::kNone);
  for (int i = 0; i < 9; ++i) watch.observe(f++, true, false);
  EXPECT_EQ(watch.observe(f++, true, false), Event::kSilent);
}

TEST(SilenceWatch, AMatchedWriterThatNeverWritesIsSilent) {
  SilenceWatch watch(5);
  EXPECT_EQ(watch.observe(100, false, false), Event::kNone);  // nobody matched: nothing to watch
  EXPECT_EQ(watch.observe(101, true, false), Event::kNone);   // matched: counting starts
  for (std::uint64_t f = 102; f < 106; ++f) EXPECT_EQ(watch.observe(f, true, false), Event::kNone);
  EXPECT_EQ(watch.observe(106, true, false), Event::kSilent);
}

TEST(SilenceWatch, AJoiningWriterGetsTheFirstSampleLimitThenTheShortOne) {
  SilenceWatch watch(5);
  watch.set_first_sample_frames(50);
  watch.observe(1, true, false);
  for (std::uint64_t f = 2; f < 51; ++f) EXPECT_EQ(watch.observe(f, true, false), Event::kNone) << f;  // joining
  EXPECT_EQ(watch.observe(51, true, true), Event::kNone);  // its first sample, at 50 frames
  for (std::uint64_t f = 52; f < 56; ++f) EXPECT_EQ(watch.observe(f, true, false), Event::kNone);
  EXPECT_EQ(watch.observe(56, true, false), Event::kSilent);  // then 5 frames, not 50
  // A writer that unmatches and matches again is a new writer: the first-sample limit again.
  watch.observe(57, false, false);
  watch.observe(58, true, false);
  for (std::uint64_t f = 59; f < 108; ++f) EXPECT_EQ(watch.observe(f, true, false), Event::kNone) << f;
  EXPECT_EQ(watch.observe(108, true, false), Event::kSilent);  // never wrote: 50 frames
}

TEST(SilenceWatch, TheFirstSampleLimitIsFramesInLockstepAndSecondsInRealtime) {
  EXPECT_EQ(SilenceWatch::first_sample_frames_for(10, false, 0.02), 10u);  // each frame waited
  EXPECT_EQ(SilenceWatch::first_sample_frames_for(10, true, 0.02), 250u);  // 5 s at 50 Hz
  EXPECT_EQ(SilenceWatch::first_sample_frames_for(10, true, 1.0), 10u);    // never below the limit
  EXPECT_EQ(SilenceWatch::first_sample_frames_for(10, true, 0.0), 10u);    // no period known
  EXPECT_EQ(SilenceWatch::first_sample_frames_for(0, true, 0.02), 250u);   // (0: the watch is off)
}

TEST(SilenceWatch, AnUnmatchedWriterEndsTheEpisodeWithoutAnEvent) {
  SilenceWatch watch(3);
  watch.observe(1, true, true);
  for (std::uint64_t f = 2; f <= 4; ++f) watch.observe(f, true, false);
  EXPECT_TRUE(watch.silent());
  EXPECT_EQ(watch.observe(5, false, false), Event::kNone);
  EXPECT_FALSE(watch.silent());
  EXPECT_EQ(watch.observe(6, true, true), Event::kNone);  // a new writer: not a "resumed"
}

TEST(SilenceWatch, ZeroLimitTurnsItOff) {
  SilenceWatch watch(0);
  watch.observe(1, true, true);
  for (std::uint64_t f = 2; f < 10000; ++f) EXPECT_EQ(watch.observe(f, true, false), Event::kNone);
}

}  // namespace
}  // namespace fedsim::timing
