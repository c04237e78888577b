// sc_main for GoogleTest binaries that touch SystemC (VCML's harness pattern):
// libsystemc.so calls sc_main, so the tests run from here. SystemC warnings and
// errors become test failures; info messages are kept off stdout.
#include <gtest/gtest.h>

#include <cstdlib>
#include <systemc>

namespace {

void report_to_gtest(const sc_core::sc_report& report, const sc_core::sc_actions& actions) {
    if (report.get_severity() >= sc_core::SC_WARNING) {
        ADD_FAILURE() << "SystemC "
                      << (report.get_severity() == sc_core::SC_WARNING ? "warning" : "error")
                      << " [" << report.get_msg_type() << "] " << report.get_msg() << " at "
                      << report.get_file_name() << ":" << report.get_line_number();
    }
    if (actions & sc_core::SC_THROW) throw report;
    if (actions & sc_core::SC_ABORT) std::abort();
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    // One time resolution everywhere, before any sc_time exists: 1 fs, the
    // precision of the RTL's `timescale 1ns / 1fs` (docs/design-brief.md, "Time").
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    sc_core::sc_report_handler::set_handler(report_to_gtest);
    // Errors must stop the offending test, not the process: throw, caught by gtest.
    sc_core::sc_report_handler::set_actions(sc_core::SC_ERROR, sc_core::SC_THROW);
    sc_core::sc_report_handler::set_actions(sc_core::SC_FATAL, sc_core::SC_THROW);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
