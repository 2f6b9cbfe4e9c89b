# SPDX-License-Identifier: GPL-3.0-or-later
"""A run in which no test passed (everything skipped) fails: it would prove nothing."""


def pytest_sessionfinish(session, exitstatus):
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    passed = len(reporter.stats.get("passed", [])) if reporter else 0
    if exitstatus == 0 and passed == 0:
        if reporter:
            reporter.write_line("no test passed (all skipped): failing the run", red=True)
        session.exitstatus = 1
