#pragma once
// A `throng-cli run --trajectories` CSV read back for checks recomputed in the tests, and
// the small geometry those checks use (written here, not taken from simcore, so that a
// test does not re-run the code it checks). Test-only.

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace throng::test {

struct TrajectoryRow {
    double x = 0.0, z = 0.0;  // m, ground plane
    double headingDeg = 0.0;  // counter-clockwise from +x seen from above
    double speed = 0.0;       // m/s
};

// Per agent id, per frame (frames in order, every frame the agent was there).
struct TrajectoryTable {
    std::map<std::uint32_t, std::map<int, TrajectoryRow>> agents;
    int frames = 0;  // highest frame + 1

    static TrajectoryTable read(const QString& path)
    {
        TrajectoryTable t;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
            return t;
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        for (qsizetype k = 1; k < lines.size(); ++k) {
            const QStringList c = lines[k].split(',');
            if (c.size() < 9)
                continue;
            const int frame = c[0].toInt();
            TrajectoryRow r;
            r.x = c[2].toDouble();
            r.z = c[4].toDouble();
            r.headingDeg = c[5].toDouble();
            r.speed = c[6].toDouble();
            t.agents[c[1].toUInt()][frame] = r;
            t.frames = std::max(t.frames, frame + 1);
        }
        return t;
    }
};

inline QJsonObject readStats(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

// A light's phase at time t: 'G', 'Y' or 'R' (the scene format's cycle: green, yellow,
// red, shifted by offset).
struct LightTiming {
    double green = 20.0, yellow = 3.0, red = 23.0, offset = 0.0;
    char phaseAt(double t) const
    {
        const double cycle = green + yellow + red;
        double u = std::fmod(t + offset, cycle);
        if (u < 0.0)
            u += cycle;
        return u < green ? 'G' : (u < green + yellow ? 'Y' : 'R');
    }
};

// Proper crossing of segments p0-p1 and a-b (touching does not count).
inline bool segmentsCrossD(double p0x, double p0z, double p1x, double p1z, double ax, double az, double bx, double bz)
{
    auto side = [](double ox, double oz, double ux, double uz, double px, double pz) {
        return (ux - ox) * (pz - oz) - (uz - oz) * (px - ox);
    };
    const double d1 = side(ax, az, bx, bz, p0x, p0z), d2 = side(ax, az, bx, bz, p1x, p1z);
    const double d3 = side(p0x, p0z, p1x, p1z, ax, az), d4 = side(p0x, p0z, p1x, p1z, bx, bz);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

}  // namespace throng::test
