#include "model/emif/emif_pins_sc.h"

#include "model/time/sc_ticks.h"

namespace emif {

emif_pins_sc::emif_pins_sc(sc_core::sc_module_name name, emif_async_master& engine)
    : sc_core::sc_module(name),
      eclkout("eclkout"),
      ce0_n("ce0_n"),
      ce1_n("ce1_n"),
      ce2_n("ce2_n"),
      ce3_n("ce3_n"),
      ea("ea"),
      be_n("be_n"),
      ed_out("ed_out"),
      ed_oe("ed_oe"),
      aoe_n("aoe_n"),
      are_n("are_n"),
      awe_n("awe_n"),
      ed_in("ed_in"),
      ardy("ardy"),
      m_engine(engine) {
    SC_HAS_PROCESS(emif_pins_sc);
    SC_METHOD(on_rising_edge);
    sensitive << eclkout.pos();
    dont_initialize();
    const emif_pins& p = engine.pins();
    ce0_n.initialize(p.ce_n[0]);
    ce1_n.initialize(p.ce_n[1]);
    ce2_n.initialize(p.ce_n[2]);
    ce3_n.initialize(p.ce_n[3]);
    ea.initialize(p.ea);
    be_n.initialize(p.be_n);
    ed_out.initialize(p.ed_out);
    ed_oe.initialize(p.ed_oe);
    aoe_n.initialize(p.aoe_n);
    are_n.initialize(p.are_n);
    awe_n.initialize(p.awe_n);
}

void emif_pins_sc::on_rising_edge() {
    const uint64_t edge = m_engine.next_edge();
    if (simtime::sc_time_of(m_engine.edge_tick(edge)) != sc_core::sc_time_stamp())
        SC_REPORT_ERROR(name(), "ECLKOUT edge off the engine's clock");
    emif_inputs in;
    in.ed_in = ed_in.read();
    in.ardy = ardy.read();
    m_engine.step(in);
    drive(m_engine.pins());
}

void emif_pins_sc::drive(const emif_pins& p) {
    ce0_n.write(p.ce_n[0]);
    ce1_n.write(p.ce_n[1]);
    ce2_n.write(p.ce_n[2]);
    ce3_n.write(p.ce_n[3]);
    ea.write(p.ea);
    be_n.write(p.be_n);
    ed_out.write(p.ed_out);
    ed_oe.write(p.ed_oe);
    aoe_n.write(p.aoe_n);
    are_n.write(p.are_n);
    awe_n.write(p.awe_n);
}

}  // namespace emif
