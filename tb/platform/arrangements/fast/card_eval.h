// The card's evaluation at a clock edge in the fast island, without the
// parts of Verilator 5.006's generated eval loop that cannot change anything
// on this card (issue 14; docs/performance.md).
//
// Verilator's eval (Vcard___024root___eval) runs, each time:
//   1. the input-combinational region (ico): the logic that reads the card's
//      inputs, recomputed from the inputs and the state;
//   2. the active/NBA loop: evaluate the six edge triggers, OR them into the
//      NBA set, run the (empty) active region, evaluate the triggers again,
//      run the NBA region (the flops), clear, evaluate the triggers once
//      more, until none fires.
// Here the same generated functions run in the same order, less two things:
//   - the ico region only when an input other than a clock changed since
//     the last eval. After any eval every combinational signal is settled on
//     the inputs and the state of that moment (Verilator repeats the
//     input-driven logic in the NBA region where it reads state:
//     nba_sequent__TOP__5 begins with reg_wr_en, rd_start, ardy), so an ico
//     run on the same inputs writes the values it finds. The card reads its
//     clocks only in its triggers (no clock in the ico logic), which the
//     lowered-clock bookkeeping (fast_island.cpp) already relies on.
//   - the trigger evaluation after the active region: that region is empty
//     on this card (Vcard___024root___eval_act has no body), so nothing can
//     have changed between the two evaluations and the second finds no edge.
// The NBA loop still iterates until no trigger fires (the internal reset
// synchronizers' outputs are triggers too), with Verilator's bound. After an
// NBA pass the triggers are evaluated again only if one of those two
// outputs moved: the other trigger sources are inputs (both clocks and
// rst_n), which the NBA region does not write, so with every source at its
// recorded previous value each trigger term is 0 and each "previous value"
// store rewrites what is there. A card that gains a trigger takes
// Verilator's eval (takes_lean_eval below).
//
// The names are Verilator 5.006's: a Verilator that renames them fails to
// link here rather than running wrong. Exactness is shown byte by byte
// against Verilator's eval (tests/rtl/test_card_eval.cpp) and by the
// arrangement identity tests (the pins arrangement runs Verilator's loop).
#pragma once

#include <cstddef>
#include <cstdlib>
#include <type_traits>
#include <utility>

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace
// (where <systemc.h> would put it). The card is --cc: it never calls it.
#ifdef SYSTEMC_VERSION
using sc_core::sc_time_stamp;
#endif
#include "Vcard.h"
#include "Vcard__Syms.h"
#include "Vcard___024root.h"
#include "verilated.h"

// The generated regions (Vcard___024root__DepSet_*.cpp; external linkage,
// declared only there).
void Vcard___024root___eval_ico(Vcard___024root* vlSelf);
void Vcard___024root___eval_triggers__act(Vcard___024root* vlSelf);
void Vcard___024root___eval_nba(Vcard___024root* vlSelf);

namespace fast {

// Whether a verilated card has the evaluation shape the lean path below is
// written for: Verilator's untraced card with six triggers (posedge eclk or
// negedge erst_n, posedge pclk or negedge rst_n, ...:
// Vcard___024root___eval_triggers__act). Another trigger means another
// source, which internal_triggers_steady would have to learn of; a card
// whose RTL changed that way (a user's, a mutant) takes Verilator's own
// eval instead, at Verilator's speed (tests/rtl/test_card_eval.cpp checks
// that the shipped card takes the lean path).
template <class card_model, class = void>
struct has_lean_eval_shape : std::false_type {};
template <class card_model>
struct has_lean_eval_shape<card_model,
                           std::void_t<decltype(std::declval<card_model&>().rootp->__VactTriggered)>>
    : std::bool_constant<std::is_same_v<card_model, Vcard> &&
                         std::is_same_v<decltype(std::declval<card_model&>().rootp->__VactTriggered),
                                        VlTriggerVec<6>>> {};
template <class card_model>
inline constexpr bool takes_lean_eval = has_lean_eval_shape<card_model>::value;

// The only trigger sources the NBA region can move: the reset synchronizers'
// outputs (rtl/reset_sync.v in rtl/card_top.v), unchanged since the last
// trigger evaluation. A template so that a card without them still builds.
template <class card_root>
inline bool internal_triggers_steady(const card_root& r) {
    return r.card_top__DOT__erst_n == r.__Vtrigrprev__TOP__card_top__DOT__erst_n &&
           r.card_top__DOT__prst_n == r.__Vtrigrprev__TOP__card_top__DOT__prst_n;
}

// The fired triggers into the NBA set one byte at a time. The trigger
// function has just stored them a byte at a time, and the wider loads of a
// plain copy cannot take bytes from several pending stores: they wait for
// those stores to retire (the island loop's hottest instruction in perf).
// The empty asm keeps the compiler from merging the byte loads again.
template <size_t count>
inline void copy_fired_triggers(VlTriggerVec<count>& to, VlTriggerVec<count>& from) {
    for (size_t i = 0; i < count; ++i) {
        bool fired = from.at(i);
        asm volatile("" : "+r"(fired));
        to.at(i) = fired;
    }
}

// The untraced card of the lean shape: the regions above, in Verilator's
// order. A template on the root so that nothing here is compiled for a card
// of another shape.
template <class card_model, class card_root>
void lean_card_eval(card_model& d, card_root& r, bool inputs_changed) {
    if (VL_UNLIKELY(!r.vlSymsp->__Vm_didInit)) {  // the first eval initializes the model
        d.eval();
        return;
    }
    if (inputs_changed) {
        r.__VicoTriggered.at(0U) = true;  // as the ico trigger on its first pass
        Vcard___024root___eval_ico(&r);
    }
    // Verilator's bound on the NBA loop (its "NBA region did not converge":
    // a 102nd pass).
    constexpr int max_nba_passes = 101;
    Vcard___024root___eval_triggers__act(&r);
    for (int pass = 0; r.__VactTriggered.any(); ++pass) {
        if (pass >= max_nba_passes) {
            VL_FATAL_MT(__FILE__, __LINE__, "", "the card's NBA region did not converge");
            std::abort();
        }
        copy_fired_triggers(r.__VnbaTriggered, r.__VactTriggered);
        Vcard___024root___eval_nba(&r);
        // No clear of the fired set on the way out: every eval (this one or
        // Verilator's) evaluates the triggers before it reads them.
        if (internal_triggers_steady(r)) break;
        Vcard___024root___eval_triggers__act(&r);
    }
    Verilated::endOfThreadMTask(r.vlSymsp->__Vm_evalMsgQp);
    Verilated::endOfEval(r.vlSymsp->__Vm_evalMsgQp);
}

// A clock edge's evaluation of any card: the lean path where the card has
// its shape, Verilator's own eval otherwise (the traced cards, whose tracer
// also reads the activity flags eval_step sets; a card of another shape).
template <class card_model>
void card_eval(card_model& d, bool inputs_changed) {
    if constexpr (takes_lean_eval<card_model>) {
        lean_card_eval(d, *d.rootp, inputs_changed);
    } else {
        (void)inputs_changed;
        d.eval();
    }
}

}  // namespace fast
