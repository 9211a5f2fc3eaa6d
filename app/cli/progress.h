#pragma once
// Progress of a long command on stderr. On a terminal: one bar redrawn in place,
//   "\r[#####     ]  50% 150/300 frames"
// at most ~20 times a second; otherwise (a log, a pipe, CI) a plain line every 10 %:
//   "bake-motion: 150/300 frames (50%)".

#include <chrono>
#include <cstdio>
#include <string>

namespace thespis::cli {

class ProgressReporter {
public:
    /// `label` prefixes plain lines; `unit` names what is counted ("frames"). Quiet prints nothing.
    ProgressReporter(std::FILE* out, std::string label, std::string unit, long total, bool quiet);
    ~ProgressReporter();

    /// Reports that `done` of total units are finished; cheap when nothing needs printing.
    void update(long done);
    /// Draws the final state and ends the bar's line.
    void finish();
    /// Ends the bar's line without drawing 100 % (cancel or failure).
    void abandon();

    bool isTerminal() const { return m_terminal; }

private:
    void drawBar(long done);

    std::FILE* m_out;
    std::string m_label, m_unit;
    long m_total;
    bool m_quiet, m_terminal;
    bool m_open = false; // a bar line is on screen without its newline
    int m_lastDecile = -1;
    std::chrono::steady_clock::time_point m_lastDraw{};
};

} // namespace thespis::cli
