// The runs of the smoke and full campaigns (docs/fault-contract.md "The
// campaign"): which faults, seeds, lengths and card settings.
#include <sstream>

#include "tb/app/faults/campaign.h"

namespace faults {

namespace {

struct plan_entry {
    const char* fault;  // nullptr: clean; several specs space-separated
    int frames;
    int retry_limit;
    const char* settings = nullptr;  // space-separated KEY=VALUE for --set
};

// Short runs (CI): every one-sensor kind and regime on both sensors, bus and
// CPU faults alone and combined with a sensor fault, the modes (sequential,
// DSK v3), and the soak rows below. Faults that must end in a hard error run
// with RETRY_LIMIT 2 so the firmware's give-up bound, (1 + 1) x (2 + 1) + 2 =
// 8 periods, fits in 10 frames.
const plan_entry smoke_faults[] = {
    {"skew:sensor=R,lines=3@frame=4", 8, 8},
    {"skew:sensor=L,lines=3@frame=4", 8, 8},
    {"skew:sensor=L,pixels=1@frame=2", 8, 8},
    {"skew:sensor=R,pixels=1@frame=2", 8, 8},
    // RETRY_LIMIT 0: every failed check is a card hard error and a firmware
    // re-arm; two of them with good pairs between must not add up to a
    // give-up. Seed 3's starts after each re-arm are in step by the truth
    // (two out-of-step starts in a row would make the give-up right).
    {"skew:sensor=R,lines=3@frame=3 skew:sensor=L,lines=2@frame=7", 12, 0},
    {"drop-line:sensor=L,line=100@frame=4", 8, 8},
    {"drop-line:sensor=R,line=100@frame=4", 8, 8},
    {"drop-frame:sensor=R@frame=4", 8, 8},
    {"drop-frame:sensor=L@frame=4", 8, 8},
    {"extra-frame:sensor=L@frame=4", 8, 8},
    {"extra-frame:sensor=R@frame=4", 8, 8},
    {"drift:sensor=R,ppm=1", 8, 8},
    {"drift:sensor=L,ppm=1", 8, 8},
    {"drift:sensor=R,ppm=200", 10, 2},
    {"drift:sensor=L,ppm=200", 10, 2},
    {"glitch:sensor=L,signal=href@ms=130.2", 10, 8},
    {"glitch:sensor=R,signal=href@ms=130.2", 10, 8},
    {"glitch:sensor=R,signal=vsync@ms=100", 8, 8},
    {"glitch:sensor=L,signal=vsync@ms=100", 8, 8},
    // 48 - 6 sigma >= 32: flagged every frame; 48 + 6 sigma < 64: a
    // threshold programmed one bit off would never see it.
    {"dark-leak:sensor=R,level=48@frame=2", 10, 2},
    {"dark-leak:sensor=L,level=48@frame=2", 10, 2},
    {"dark-leak:sensor=L,level=8", 8, 8},
    {"dark-leak:sensor=R,level=8", 8, 8},
    {"stuck-bit:sensor=L,bit=7", 10, 2},
    {"stuck-bit:sensor=R,bit=7", 10, 2},
    {"stuck-bit:sensor=R,bit=0", 8, 8},
    {"stuck-bit:sensor=L,bit=0", 8, 8},
    {"dead:sensor=R", 10, 2},
    {"dead:sensor=L", 10, 2},
    {"oe-stuck:sensor=L", 10, 2},
    {"oe-stuck:sensor=R", 10, 2},
    // Both sensors silent and a START_TIMEOUT longer than the run: the card
    // never flags anything, only the firmware's own watchdog can give up.
    {"dead:sensor=L dead:sensor=R", 10, 2,
     "firmware.watchdog_ms=50 firmware.card_start_timeout=65535"},
    // The same on DSK v3 (a 1 GHz CPU: the watchdog's timer period).
    {"dead:sensor=L dead:sensor=R", 10, 2,
     "firmware.watchdog_ms=50 firmware.card_start_timeout=65535 dsk.version=3"},
    // Both silent with a START_TIMEOUT of one frame: the card's own start
    // timeout fails each start, RETRY_LIMIT restarts, HARD_ERROR.
    {"dead:sensor=L dead:sensor=R", 10, 2, "firmware.card_start_timeout=525"},
    // A card that falls silent after it has shown events: seed 3's first
    // start is out of step, and both sensors ignore the card's restart.
    {"dead:sensor=L@ms=10 dead:sensor=R@ms=10", 10, 2,
     "firmware.watchdog_ms=50 firmware.card_start_timeout=65535"},
    // A persistent fault under a watchdog shorter than the give-up: its
    // ticks see the card's failed checks as progress.
    {"dark-leak:sensor=L,level=48@frame=3", 14, 4, "firmware.watchdog_ms=100"},
    {"emif-wait:cycles=40@frame=3", 8, 8},
    {"cpu-slow:factor=20@frame=4", 14, 8},
    // A bus or CPU fault with a sensor fault in effect at the same time.
    {"cpu-slow:factor=3@frame=3 skew:sensor=L,lines=3@frame=5", 14, 8},
    {"emif-wait:cycles=2@frame=2 drop-frame:sensor=R@frame=5", 12, 8},
    {"emif-wait:cycles=30@frame=3 dark-leak:sensor=L,level=48@frame=5", 12, 2},
    // A CPU that overruns every other period and a bus that overflows the
    // card's FIFOs: the overflow re-arms come while the overrun policy is
    // dropping pairs, and each drop must still be counted and reported.
    {"cpu-slow:factor=6@frame=2 emif-wait:cycles=40@frame=8", 20, 8},
    // A sensor that dies at the overflow re-arm's OE rise (sequential
    // capture loses the pair in flight with it): the re-arm that follows
    // the card's hard error is the firmware's one re-arm, not its give-up.
    {"emif-wait:cycles=40@frame=3 dead:sensor=L@ms=80", 14, 2, "firmware.mode=sequential"},
    // The modes: sequential capture, DSK v3.
    {"skew:sensor=R,lines=3@frame=4", 8, 8, "firmware.mode=sequential"},
    {"drop-frame:sensor=L@frame=4", 8, 8, "dsk.version=3"},
};

// Soak rows: longer than every time constant of the design. A clean run of
// three default watchdog periods (500 ms each: 64 x 24.5 ms = 1.57 s), ten
// one-frame faults on alternating sensors spaced by good frames (more than
// RETRY_LIMIT 8: none may add up to a hard error), and a slow drift that
// slips every few frames (+1 ppm: 0.41 clock a frame).
constexpr const char* ten_intermittent_faults =
    "skew:sensor=L,lines=3@frame=4 drop-line:sensor=R,line=100@frame=9 "
    "drop-frame:sensor=L@frame=14 skew:sensor=R,pixels=1@frame=19 "
    "drop-line:sensor=L,line=300@frame=24 drop-frame:sensor=R@frame=29 "
    "skew:sensor=R,lines=2@frame=34 drop-line:sensor=R,line=20@frame=39 "
    "skew:sensor=L,pixels=2@frame=44 drop-frame:sensor=L@frame=49";

const plan_entry smoke_soak[] = {
    {nullptr, 64, 8},
    {ten_intermittent_faults, 54, 8},
    {"drift:sensor=L,ppm=1", 64, 8},
};
const plan_entry full_faults[] = {
    {"skew:sensor=R,lines=1@frame=4", 14, 8},
    {"skew:sensor=L,lines=3@frame=5", 14, 8},
    {"skew:sensor=R,lines=40@frame=3", 14, 8},
    {"skew:sensor=L,pixels=1@frame=2", 14, 8},
    {"skew:sensor=R,pixels=7@frame=6", 14, 8},
    {"drop-line:sensor=L,line=0@frame=4", 14, 8},
    {"drop-line:sensor=R,line=100@frame=7", 20, 8},
    {"drop-line:sensor=L,line=500@frame=3", 14, 8},
    {"drop-frame:sensor=R@frame=4", 14, 8},
    {"drop-frame:sensor=L@frame=6", 14, 8},
    {"extra-frame:sensor=L@frame=4", 14, 8},
    {"drift:sensor=R,ppm=1", 20, 8},
    {"drift:sensor=L,ppm=-1", 20, 8},
    {"drift:sensor=R,ppm=200", 10, 2},
    {"drift:sensor=L,ppm=-50", 10, 2},
    {"glitch:sensor=L,signal=href@ms=130.2", 14, 8},
    {"glitch:sensor=R,signal=href,width=50@ms=100", 14, 8},
    {"glitch:sensor=R,signal=vsync@ms=100", 14, 8},
    {"glitch:sensor=L,signal=vsync,width=50@ms=150.7", 14, 8},
    {"dark-leak:sensor=L,level=8", 14, 8},
    {"dark-leak:sensor=R,level=40@frame=2", 10, 2},
    {"dark-leak:sensor=R,level=80@frame=2", 10, 2},
    {"stuck-bit:sensor=L,bit=0", 14, 8},
    {"stuck-bit:sensor=R,bit=3", 14, 8},
    {"stuck-bit:sensor=L,bit=4", 14, 8},
    {"stuck-bit:sensor=R,bit=5", 10, 2},
    {"stuck-bit:sensor=L,bit=7", 10, 2},
    {"stuck-bit:sensor=R,bit=7,value=0", 14, 8},
    {"dead:sensor=L", 10, 2},
    {"dead:sensor=R", 10, 2},
    {"dead:sensor=L dead:sensor=R", 10, 2,
     "firmware.watchdog_ms=50 firmware.card_start_timeout=65535"},
    {"oe-stuck:sensor=L", 10, 2},
    {"oe-stuck:sensor=R", 10, 2},
    {"emif-wait:cycles=2@frame=3", 14, 8},
    {"emif-wait:cycles=40@frame=3", 14, 8},
    {"emif-wait:cycles=40,ce=2@frame=3", 14, 8},
    {"cpu-slow:factor=1.5@frame=4", 14, 8},
    {"cpu-slow:factor=3@frame=4", 14, 8},
    {"cpu-slow:factor=20@frame=4", 20, 8},
};

// Full campaign, every seed: the soak rows longer, on both sensors, the
// combined rows and their mirrors, the special rows of the smoke campaign.
const plan_entry full_soak[] = {
    {nullptr, 64, 8},
    {nullptr, 100, 8},
    {ten_intermittent_faults, 54, 8},
    {"skew:sensor=R,lines=3@frame=4 drop-line:sensor=L,line=100@frame=9 "
     "drop-frame:sensor=R@frame=14 skew:sensor=L,pixels=1@frame=19 "
     "drop-line:sensor=R,line=300@frame=24 drop-frame:sensor=L@frame=29 "
     "skew:sensor=L,lines=2@frame=34 drop-line:sensor=L,line=20@frame=39 "
     "skew:sensor=R,pixels=2@frame=44 drop-frame:sensor=R@frame=49 "
     "skew:sensor=L,lines=1@frame=54 drop-frame:sensor=R@frame=59",
     64, 8},
    {"drift:sensor=L,ppm=1", 80, 8},
    {"drift:sensor=R,ppm=1", 80, 8},
    {"cpu-slow:factor=3@frame=3 skew:sensor=L,lines=3@frame=5", 14, 8},
    {"cpu-slow:factor=3@frame=3 skew:sensor=R,lines=3@frame=5", 14, 8},
    {"cpu-slow:factor=20@frame=4 drop-frame:sensor=L@frame=6", 20, 8},
    // 24 frames: after the drop, seed 13's restarts fail six times before
    // one starts in step (its bound: 490 ms, 20 periods).
    {"emif-wait:cycles=2@frame=2 drop-frame:sensor=R@frame=5", 24, 8},
    {"emif-wait:cycles=2@frame=2 drop-frame:sensor=L@frame=5", 24, 8},
    {"emif-wait:cycles=30@frame=3 dark-leak:sensor=L,level=48@frame=5", 12, 2},
    {"emif-wait:cycles=30@frame=3 stuck-bit:sensor=R,bit=7@frame=5", 12, 2},
    {"cpu-slow:factor=6@frame=2 emif-wait:cycles=40@frame=8", 20, 8},
    {"emif-wait:cycles=40@frame=3 dead:sensor=L@ms=80", 14, 2, "firmware.mode=sequential"},
    {"emif-wait:cycles=40@frame=3 dead:sensor=R@ms=80", 14, 2, "firmware.mode=sequential"},
    {"dead:sensor=L dead:sensor=R", 10, 2, "firmware.card_start_timeout=525"},
    {"dark-leak:sensor=L,level=48@frame=3", 14, 4, "firmware.watchdog_ms=100"},
    {"dark-leak:sensor=R,level=48@frame=3", 14, 4, "firmware.watchdog_ms=100"},
};

// Full campaign, one seed (11): a representative of every kind under the
// other modes, and onsets placed in the other phases of a frame (seed 11's
// frames start at 24.738 + 24.5 k ms: dark rows 1.26-1.63 ms in, active rows
// 1.73-24.1 ms in; its card restarts OE from 24.60 to 24.64 ms).
const char* const mode_settings[] = {"firmware.mode=sequential", "dsk.version=3",
                                     "firmware.mode=sequential dsk.version=3"};
const plan_entry mode_representatives[] = {
    {"skew:sensor=L,lines=3@frame=4", 8, 8},
    {"drop-line:sensor=R,line=100@frame=4", 8, 8},
    {"drop-frame:sensor=L@frame=4", 8, 8},
    {"extra-frame:sensor=R@frame=4", 8, 8},
    {"drift:sensor=L,ppm=200", 10, 2},
    {"glitch:sensor=R,signal=vsync@ms=100", 8, 8},
    {"dark-leak:sensor=L,level=80@frame=2", 10, 2},
    {"stuck-bit:sensor=R,bit=7", 10, 2},
    {"dead:sensor=L", 10, 2},
    {"oe-stuck:sensor=R", 10, 2},
    {"emif-wait:cycles=40@frame=3", 8, 8},
    {"cpu-slow:factor=20@frame=4", 14, 8},
};
// Onsets after a late start (frame 5 and later) run long enough for the
// hard error or the recovery to fall due before the end. A glitch inside
// the OE restart reaches no pin the card reads, so no glitch row is there.
// The card that falls silent after its first events is seed 11's: the
// dead sensors act at the next OE rise, which only an out-of-step first
// start (seeds 3, 11 and 12; not 13) brings before the run ends.
const plan_entry phase_rows[] = {
    {"dead:sensor=L@ms=10 dead:sensor=R@ms=10", 10, 2,
     "firmware.watchdog_ms=50 firmware.card_start_timeout=65535"},
    {"dark-leak:sensor=R,level=80@ms=124.1", 15, 2},
    {"dark-leak:sensor=L,level=80@ms=134.7", 15, 2},
    {"dark-leak:sensor=L,level=80@ms=24.62", 10, 2},
    {"stuck-bit:sensor=L,bit=7@ms=124.1", 15, 2},
    {"stuck-bit:sensor=R,bit=7@ms=134.7", 15, 2},
    {"stuck-bit:sensor=R,bit=7@ms=24.62", 10, 2},
    {"drift:sensor=R,ppm=200@ms=124.1", 12, 2},
    {"drift:sensor=L,ppm=200@ms=134.7", 12, 2},
    {"drift:sensor=L,ppm=200@ms=24.62", 12, 2},
    {"skew:sensor=L,lines=2@ms=124.1", 13, 8},
    {"skew:sensor=R,lines=2@ms=134.7", 13, 8},
    {"glitch:sensor=L,signal=href@ms=124.1", 8, 8},
    {"glitch:sensor=R,signal=vsync@ms=123.2", 8, 8},
    {"emif-wait:cycles=40@ms=124.1", 8, 8},
    {"emif-wait:cycles=40@ms=134.7", 8, 8},
    {"emif-wait:cycles=40@ms=24.62", 8, 8},
    {"cpu-slow:factor=20@ms=124.1", 20, 8},
    {"cpu-slow:factor=20@ms=134.7", 20, 8},
    {"cpu-slow:factor=20@ms=24.62", 20, 8},
};

// Full campaign: 84 clean runs of 12 frames = 1008 clean frames.
constexpr int full_clean_runs = 84, full_clean_frames = 12;

}  // namespace

std::vector<std::string> spec_words(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::vector<campaign_run> campaign_plan(const std::string& name, int seeds) {
    std::vector<campaign_run> runs;
    const bool smoke = name == "smoke";
    if (!smoke && name != "full") return runs;
    if (seeds <= 0) seeds = smoke ? 1 : 3;
    const uint64_t first_seed = smoke ? 3 : 11;
    const auto add = [&](const plan_entry& e, uint64_t seed) {
        campaign_run r;
        r.index = static_cast<int>(runs.size());
        r.fault = e.fault ? e.fault : "";
        r.seed = seed;
        r.frames = e.frames;
        r.retry_limit = e.retry_limit;
        if (e.settings) r.settings = spec_words(e.settings);
        runs.push_back(r);
    };
    if (smoke) {
        for (int s = 0; s < 2 * seeds; ++s) add({nullptr, 8, 8}, first_seed + s);
        for (const plan_entry& e : smoke_faults)
            for (int s = 0; s < seeds; ++s) add(e, first_seed + s);
        for (const plan_entry& e : smoke_soak)
            for (int s = 0; s < seeds; ++s) add(e, first_seed + s);
    } else {
        for (int s = 0; s < full_clean_runs; ++s) add({nullptr, full_clean_frames, 8}, 100 + s);
        for (const plan_entry& e : full_faults)
            for (int s = 0; s < seeds; ++s) add(e, first_seed + s);
        for (const plan_entry& e : full_soak)
            for (int s = 0; s < seeds; ++s) add(e, first_seed + s);
        for (const char* settings : mode_settings)
            for (plan_entry e : mode_representatives) {
                e.settings = settings;
                add(e, first_seed);
            }
        for (const plan_entry& e : phase_rows) add(e, first_seed);
    }
    return runs;
}

std::vector<campaign_run> shard_of(const std::vector<campaign_run>& runs, int shard, int shards) {
    std::vector<campaign_run> out;
    for (const campaign_run& r : runs)
        if (r.index % shards == shard - 1) out.push_back(r);
    return out;
}

}  // namespace faults
