// The fast island's lean evaluation of the card (card_eval,
// tb/platform/arrangements/fast/card_eval.h) against Verilator's own eval,
// state by state. A card bench runs the card (rtl_card, the platform's
// build) through configuration, capture, interrupts, the DSP model's reads
// of every word, a reset in the middle of a frame and a second start, with
// Verilator's eval; a shadow card follows it: after every eval of the bench
// it takes the same inputs and is evaluated with card_eval. After each of
// them every byte of the two models must agree, less the scheduler's own
// bookkeeping (trigger vectors, loop counters) and each model's identity
// (its symbol table pointer, its name), named member by member; the FIFO
// memories are compared every 256 evals and at the end.
//
// Oracle: Verilator 5.006's generated eval, an implementation independent of
// card_eval's loop. Negative control: a shadow that never runs the
// input-combinational region (card_eval told that no input changed) drifts
// apart, so the comparison sees what card_eval's input tracking is for. The
// reset in mid-frame is what checks the NBA loop: the reset synchronizers'
// outputs fall inside an NBA pass and need a second one (a loop cut to one
// pass differs on 4 evals, the trigger re-evaluation always skipped on 5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "Vcard.h"
#include "Vcard___024root.h"
#include "tb/platform/arrangements/fast/card_eval.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard>;

// A byte range of the model's root.
struct byte_range {
    size_t offset = 0, size = 0;
};

template <class Member>
byte_range range_of(const Vcard___024root& root, const Member& m) {
    const auto* base = reinterpret_cast<const unsigned char*>(&root);
    const auto* at = reinterpret_cast<const unsigned char*>(&m);
    return {static_cast<size_t>(at - base), sizeof(Member)};
}

// The shadow card and what its comparison leaves out.
class shadow_card {
  public:
    // ico_tracked=false: the negative control (no input ever reported changed).
    // In the bench's context (Verilator erases a model's scopes from the
    // thread's context, so one context for both keeps their teardown sound).
    shadow_card(VerilatedContext& context, bool ico_tracked)
        : m_ico_tracked(ico_tracked), m_card(std::make_unique<Vcard>(&context, "shadow")) {}
    ~shadow_card() { m_card->final(); }

    // The bench card's reset sequence (card_bench's constructor), with
    // Verilator's eval, then what the comparison leaves out.
    void reset_like(Vcard& bench_card) {
        Vcard& s = *m_card;
        s.pclk = s.eclk = 0;
        s.rst_n = 1;
        copy_inputs(bench_card);
        s.eval();
        s.rst_n = 0;
        s.eval();
        s.rst_n = 1;
        s.eval();
        const Vcard___024root& r = *s.rootp;
        // Left out: the scheduler's bookkeeping, and each model's identity
        // (its name in the VerilatedModule base, its symbol table pointer).
        m_skip = {range_of(r, r.__VicoTriggered), range_of(r, r.__VactTriggered),
                  range_of(r, r.__VnbaTriggered), range_of(r, r.__VicoIterCount),
                  range_of(r, r.__VactIterCount), range_of(r, r.__VactContinue),
                  range_of(r, r.__VstlIterCount), range_of(r, r.__VstlTriggered),
                  {0, sizeof(VerilatedModule)},   range_of(r, r.vlSymsp)};
        m_memories = {range_of(r, r.card_top__DOT__u_fifo_l__DOT__mem),
                      range_of(r, r.card_top__DOT__u_fifo_r__DOT__mem)};
        std::vector<bool> skip(sizeof(Vcard___024root), false);
        mark(m_skip, &skip);
        skipped_bytes = static_cast<long>(std::count(skip.begin(), skip.end(), true));
        m_compared = runs_outside(skip);
        mark(m_memories, &skip);
        m_compared_but_memories = runs_outside(skip);
        equal_after_reset = same_as(bench_card, true);
    }

    // After an eval of the bench card: the same inputs, card_eval, compare.
    void follow(Vcard& bench_card) {
        const bool changed = copy_inputs(bench_card);
        fast::card_eval(*m_card, m_ico_tracked && changed);
        ++evals;
        const bool memories = evals % 256 == 0;
        if (!same_as(bench_card, memories)) ++differing_evals;
    }

    bool same_as(const Vcard& bench_card, bool with_memories) const {
        const auto* a = bytes(*bench_card.rootp);
        const auto* b = bytes(*m_card->rootp);
        for (const byte_range& g : with_memories ? m_compared : m_compared_but_memories)
            if (std::memcmp(a + g.offset, b + g.offset, g.size) != 0) return false;
        return true;
    }

    long evals = 0, differing_evals = 0;
    long skipped_bytes = 0;  // left out of every comparison
    bool equal_after_reset = false;

  private:
    static const unsigned char* bytes(const Vcard___024root& r) {
        return reinterpret_cast<const unsigned char*>(&r);
    }
    static void mark(const std::vector<byte_range>& ranges, std::vector<bool>* skip) {
        for (const byte_range& g : ranges)
            for (size_t i = g.offset; i < g.offset + g.size; ++i) (*skip)[i] = true;
    }
    // The root's bytes not skipped, as runs.
    static std::vector<byte_range> runs_outside(const std::vector<bool>& skip) {
        std::vector<byte_range> runs;
        for (size_t i = 0; i < skip.size(); ++i) {
            if (skip[i]) continue;
            if (!runs.empty() && runs.back().offset + runs.back().size == i)
                ++runs.back().size;
            else
                runs.push_back({i, 1});
        }
        return runs;
    }
    // Every input; true if one other than the clocks changed.
    bool copy_inputs(const Vcard& from) {
        Vcard& s = *m_card;
        bool changed = false;
        auto take = [&changed](auto& to, auto value) {
            if (to != value) changed = true;
            to = value;
        };
        take(s.rst_n, from.rst_n);
        take(s.l_vsync, from.l_vsync);
        take(s.l_href, from.l_href);
        take(s.l_valid, from.l_valid);
        take(s.l_data, from.l_data);
        take(s.l_fodd, from.l_fodd);
        take(s.r_vsync, from.r_vsync);
        take(s.r_href, from.r_href);
        take(s.r_valid, from.r_valid);
        take(s.r_data, from.r_data);
        take(s.r_fodd, from.r_fodd);
        take(s.ce2_n, from.ce2_n);
        take(s.ce3_n, from.ce3_n);
        take(s.aoe_n, from.aoe_n);
        take(s.are_n, from.are_n);
        take(s.awe_n, from.awe_n);
        take(s.ea, from.ea);
        take(s.be_n, from.be_n);
        take(s.ed_in, from.ed_in);
        s.pclk = from.pclk;
        s.eclk = from.eclk;
        return changed;
    }

    bool m_ico_tracked;
    std::unique_ptr<Vcard> m_card;
    std::vector<byte_range> m_skip, m_memories;
    std::vector<byte_range> m_compared, m_compared_but_memories;
};

struct followed_run {
    long evals = 0, differing_evals = 0;
    long skipped_bytes = 0;  // left out of every comparison
    bool equal_after_reset = false;
    bool memories_agree = false;
    size_t pairs_read = 0, pairs_before_reset = 0;
    uint64_t bad_words_before_reset = 0;  // the reset drops the pair being read
};

// Two starts of capture with a reset between them (mid-frame: the
// asynchronous resets and the reset synchronizers' triggers act), frames
// read word by word after each FRAME_READY.
followed_run run_followed(bool ico_tracked) {
    rtl_test::bench_options o;
    o.design = "card";
    bench b(o);
    shadow_card shadow(b.context(), ico_tracked);
    shadow.reset_like(b.dut());
    b.after_eval = [&] { shadow.follow(b.dut()); };
    b.reader_enabled = true;
    followed_run r;
    for (int start = 0; start < 2; ++start) {
        b.configure_layout(o.layout);
        b.enable(true);
        b.run_frames(4.4);
        if (start == 0) {
            r.pairs_before_reset = b.pairs.size();
            for (const auto& p : b.pairs) r.bad_words_before_reset += p.bad_words;
            b.dut().rst_n = 0;
            for (int i = 0; i < 40; ++i) b.step();
            b.dut().rst_n = 1;
            b.run_ticks(o.eclk_ticks * 20);
        }
    }
    r.evals = shadow.evals;
    r.differing_evals = shadow.differing_evals;
    r.skipped_bytes = shadow.skipped_bytes;
    r.equal_after_reset = shadow.equal_after_reset;
    r.memories_agree = shadow.same_as(b.dut(), true);
    r.pairs_read = b.pairs.size();
    return r;
}

// The shipped card has the shape the lean path is written for; a change of
// the RTL that adds a trigger would silently put the island on Verilator's
// slower eval. (Not a behaviour check: the mutant runner leaves it out.)
TEST(CardEval, TheShippedCardTakesTheLeanPath) {
    EXPECT_TRUE(fast::takes_lean_eval<Vcard>);
}

TEST(CardEval, LeanEvaluationLeavesEveryByteAsVerilatorsEvalDoes) {
    if (!fast::takes_lean_eval<Vcard>) GTEST_SKIP() << "the card takes Verilator's eval";
    const followed_run r = run_followed(true);
    EXPECT_GT(r.evals, 20000);
    // Two models reset alike are equal but for what is left out: the
    // scheduler's bookkeeping and the two identity pointers (a few words).
    EXPECT_TRUE(r.equal_after_reset);
    EXPECT_LE(r.skipped_bytes, 64);
    EXPECT_EQ(r.differing_evals, 0);
    EXPECT_TRUE(r.memories_agree);
    // The run exercised what it claims: pairs read and checked word by word
    // before the reset, and pairs read after the second start.
    EXPECT_GE(r.pairs_before_reset, 2u);
    EXPECT_EQ(r.bad_words_before_reset, 0u);
    EXPECT_GE(r.pairs_read, r.pairs_before_reset + 2);
    std::printf("evals %ld, bytes left out %ld, pairs %zu (%zu before the reset)\n", r.evals,
                r.skipped_bytes, r.pairs_read, r.pairs_before_reset);
}

TEST(CardEval, NegativeControlWithoutTheInputRegionDrifts) {
    if (!fast::takes_lean_eval<Vcard>) GTEST_SKIP() << "the card takes Verilator's eval";
    const followed_run r = run_followed(false);
    EXPECT_GT(r.differing_evals, 0);
    std::printf("evals %ld, of which differing %ld\n", r.evals, r.differing_evals);
}

}  // namespace
