#include "proveout/material.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace k528::proveout {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxColumns = 65536;

// The sweep's signed extent [lo, hi] as the radii it reaches on a part that
// turns: [u0, u1].
inline void radial(double lo, double hi, double& u0, double& u1) {
    if (lo >= 0) {
        u0 = lo;
        u1 = hi;
    } else if (hi <= 0) {
        u0 = -hi;
        u1 = -lo;
    } else {
        u0 = 0;
        u1 = std::max(-lo, hi);
    }
}
} // namespace

LatheMaterial::LatheMaterial(const stock::Blank& b, double resolutionMm) {
    const double z0 = std::min(0.0, b.outerLengthMm), z1 = std::max(0.0, b.outerLengthMm);
    const double len = z1 - z0;
    std::size_t n = static_cast<std::size_t>(std::ceil(len / std::max(resolutionMm, 1e-6) - 1e-9));
    n = std::clamp<std::size_t>(n, 1, kMaxColumns);
    n_ = n;
    z0_ = z0;
    dz_ = len / static_cast<double>(n);
    blankDiameter_ = b.outerDiameterMm;
    in_.assign(n_, 0.0);
    out_.assign(n_, 0.0);
    const double R = b.outerDiameterMm / 2;
    const double ta = std::tan(b.outerAngleDeg * kPi / 180);
    const double rb = b.boreDiameterMm / 2;
    const double lb = std::fabs(b.boreLengthMm);
    const double zb = z1 - lb;
    const double tb = std::tan(b.boreAngleDeg * kPi / 180);
    for (std::size_t i = 0; i < n_; ++i) {
        const double z = columnZ(i);
        out_[i] = std::max(0.0, R + (z - z0) * ta);
        if (rb > 0 && lb > 0 && z >= zb)
            in_[i] = std::max(0.0, rb + (z - zb) * tb);
    }
    const std::size_t blocks = (n_ + kBlock - 1) / kBlock;
    blockMinIn_.assign(blocks, 0.0);
    blockMaxOut_.assign(blocks, 0.0);
    for (std::size_t k = 0; k < blocks; ++k)
        refreshBlock(k);
    maxOuter_ = *std::max_element(out_.begin(), out_.end());
}

void LatheMaterial::refreshBlock(std::size_t k) {
    double mn = std::numeric_limits<double>::infinity(), mx = -1;
    const std::size_t e = std::min(n_, (k + 1) * kBlock);
    for (std::size_t i = k * kBlock; i < e; ++i)
        if (in_[i] < out_[i]) {
            mn = std::min(mn, in_[i]);
            mx = std::max(mx, out_[i]);
        }
    blockMinIn_[k] = mn;
    blockMaxOut_[k] = mx;
}

void LatheMaterial::span(double za, double zb, std::size_t& first, std::size_t& last) const {
    // Column i's centre z0 + dz (i + 0.5) in [za, zb].
    const double a = std::ceil((za - z0_) / dz_ - 0.5 - 1e-9);
    const double b = std::floor((zb - z0_) / dz_ - 0.5 + 1e-9) + 1;
    first = a <= 0 ? 0 : static_cast<std::size_t>(std::min(a, static_cast<double>(n_)));
    last = b <= 0 ? 0 : static_cast<std::size_t>(std::min(b, static_cast<double>(n_)));
    if (last < first)
        last = first;
}

template <class F> bool LatheMaterial::visit(const Sweep& s, F&& f) const {
    std::size_t next = 0;
    for (std::size_t k = 0; k < s.pieceCount(); ++k) {
        const Sweep::Piece& p = s.piece(k);
        std::size_t first = 0, last = 0;
        span(p.z0, p.z1, first, last);
        first = std::max(first, next);
        for (std::size_t i = first; i < last;) {
            const std::size_t b = i / kBlock;
            const std::size_t e = std::min(last, (b + 1) * kBlock);
            if (blockMaxOut_[b] < 0) { // an empty block
                i = e;
                continue;
            }
            const double za = columnZ(i), zb = columnZ(e - 1);
            const double loMin = std::min(p.loA + p.loB * za, p.loA + p.loB * zb);
            const double hiMax = std::max(p.hiA + p.hiB * za, p.hiA + p.hiB * zb);
            const double u0Bound = loMin >= 0 ? loMin : (hiMax <= 0 ? -hiMax : 0.0);
            const double u1Bound = std::max(std::fabs(loMin), std::fabs(hiMax));
            if (u0Bound >= blockMaxOut_[b] - kEpsMm || u1Bound <= blockMinIn_[b] + kEpsMm) {
                i = e;
                continue;
            }
            if (loMin >= 0) { // the usual case: the sweep stays on one side of the axis
                for (; i < e; ++i) {
                    if (in_[i] >= out_[i])
                        continue;
                    const double z = z0_ + dz_ * (static_cast<double>(i) + 0.5);
                    if (!f(i, p.loA + p.loB * z, p.hiA + p.hiB * z))
                        return false;
                }
            } else {
                for (; i < e; ++i) {
                    if (in_[i] >= out_[i])
                        continue;
                    const double z = z0_ + dz_ * (static_cast<double>(i) + 0.5);
                    double u0 = 0, u1 = 0;
                    radial(p.loA + p.loB * z, p.hiA + p.hiB * z, u0, u1);
                    if (!f(i, u0, u1))
                        return false;
                }
            }
        }
        next = std::max(next, last);
    }
    return true;
}

bool LatheMaterial::mayTouch(const Box& b) const {
    if (b.z1 < z0_ || b.z0 > zMax())
        return false;
    const double rMin = b.r0 >= 0 ? b.r0 : (b.r1 <= 0 ? -b.r1 : 0.0);
    return rMin < maxOuter_ - kEpsMm;
}

bool LatheMaterial::touches(Sweep& s) const {
    return !visit(s, [&](std::size_t i, double u0, double u1) {
        return std::min(out_[i], u1) - std::max(in_[i], u0) <= kEpsMm;
    });
}

LatheMaterial::Cut LatheMaterial::cut(Sweep& s, double dz, double dr) {
    Cut c;
    const double len = std::hypot(dz, dr);
    const double nz = len > 0 ? -dr / len : 0, nr = len > 0 ? dz / len : 0; // across
    const double uz = nr, ur = -nz;                                          // along
    double pMin = std::numeric_limits<double>::infinity(), pMax = -pMin;
    double qMin = pMin, qMax = -pMin;
    std::size_t changedBlock = static_cast<std::size_t>(-1);
    visit(s, [&](std::size_t i, double u0, double u1) {
        double& in = in_[i];
        double& out = out_[i];
        const double a = std::max(in, u0), b = std::min(out, u1);
        if (b - a <= kEpsMm)
            return true;
        c.any = true;
        c.areaMm2 += (b - a) * dz_;
        const double zc = columnZ(i);
        pMin = std::min(pMin, std::min(zc * nz + a * nr, zc * nz + b * nr));
        pMax = std::max(pMax, std::max(zc * nz + a * nr, zc * nz + b * nr));
        qMin = std::min(qMin, std::min(zc * uz + a * ur, zc * uz + b * ur));
        qMax = std::max(qMax, std::max(zc * uz + a * ur, zc * uz + b * ur));
        if (u0 <= in + kEpsMm)
            in = std::max(in, u1);
        else if (u1 >= out - kEpsMm)
            out = std::min(out, u0);
        else
            in = u1; // buried: the bore opens up to the sweep's top
        if (in >= out - kEpsMm)
            in = out = 0;
        const std::size_t blk = i / kBlock;
        if (blk != changedBlock) {
            if (changedBlock != static_cast<std::size_t>(-1))
                refreshBlock(changedBlock);
            changedBlock = blk;
        }
        return true;
    });
    if (changedBlock != static_cast<std::size_t>(-1))
        refreshBlock(changedBlock);
    if (c.any && len > 0) {
        c.depthMm = pMax - pMin + std::fabs(nz) * dz_;
        c.alongMm = qMax - qMin + std::fabs(uz) * dz_;
    }
    return c;
}

double LatheMaterial::areaMm2() const {
    double a = 0;
    for (std::size_t i = 0; i < n_; ++i)
        if (in_[i] < out_[i])
            a += (out_[i] - in_[i]) * dz_;
    return a;
}

} // namespace k528::proveout
