#include "progress.h"

#include <algorithm>
#include <unistd.h>

namespace thespis::cli {
namespace {

constexpr int BarWidth = 30;
constexpr auto RedrawInterval = std::chrono::milliseconds(50);

} // namespace

ProgressReporter::ProgressReporter(std::FILE* out, std::string label, std::string unit, long total, bool quiet)
    : m_out(out), m_label(std::move(label)), m_unit(std::move(unit)), m_total(std::max(1L, total)), m_quiet(quiet),
      m_terminal(::isatty(fileno(out)) == 1)
{
}

ProgressReporter::~ProgressReporter()
{
    abandon();
}

void ProgressReporter::update(long done)
{
    if (m_quiet)
        return;
    done = std::clamp(done, 0L, m_total);
    if (m_terminal) {
        const auto now = std::chrono::steady_clock::now();
        if (m_open && now - m_lastDraw < RedrawInterval)
            return;
        m_lastDraw = now;
        drawBar(done);
        return;
    }
    const int decile = int(done * 10 / m_total);
    if (decile == m_lastDecile)
        return;
    m_lastDecile = decile;
    std::fprintf(m_out, "%s: %ld/%ld %s (%d%%)\n", m_label.c_str(), done, m_total, m_unit.c_str(),
                 int(done * 100 / m_total));
    std::fflush(m_out);
}

void ProgressReporter::drawBar(long done)
{
    const int filled = int(done * BarWidth / m_total);
    std::string bar(std::size_t(filled), '#');
    bar.append(std::size_t(BarWidth - filled), ' ');
    std::fprintf(m_out, "\r[%s] %3d%% %ld/%ld %s", bar.c_str(), int(done * 100 / m_total), done, m_total,
                 m_unit.c_str());
    std::fflush(m_out);
    m_open = true;
}

void ProgressReporter::finish()
{
    if (m_quiet)
        return;
    if (m_terminal)
        drawBar(m_total);
    else if (m_lastDecile != 10)
        update(m_total);
    abandon();
}

void ProgressReporter::abandon()
{
    if (m_open) {
        std::fputc('\n', m_out);
        std::fflush(m_out);
        m_open = false;
    }
}

} // namespace thespis::cli
