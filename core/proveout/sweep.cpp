#include "proveout/sweep.h"

#include <algorithm>
#include <cmath>

namespace k528::proveout {

namespace {

// r of the chain c (n points, z ascending) at z, walking from index i.
double chainAt(const std::array<PointZR, 8>& c, std::size_t n, std::size_t& i, double z) {
    if (n == 1)
        return c[0].r;
    if (z <= c[0].z) {
        i = 0;
        return c[0].r;
    }
    if (i + 1 < n && z < c[i].z)
        i = 0;
    while (i + 2 < n && z > c[i + 1].z)
        ++i;
    const PointZR a = c[i], b = c[i + 1];
    if (b.z <= a.z)
        return std::max(a.r, b.r);
    const double t = std::clamp((z - a.z) / (b.z - a.z), 0.0, 1.0);
    return a.r + (b.r - a.r) * t;
}

} // namespace

Sweep::Sweep(const Box& b, PointZR from, PointZR to) {
    // The hull of a box and its copy moved along Z is a hexagon whose chains
    // follow from the direction of the motion: with L the box further along
    // -Z and R the other, moving up (dr >= 0) the lower chain runs along L's
    // bottom to R's bottom-right corner and the upper one from L's top-left
    // to R's top; moving down the other way round.
    PointZR pa = from, pb = to;
    if (pb.z < pa.z)
        std::swap(pa, pb);
    const Box L = b.moved(pa), R = b.moved(pb);
    if (pb.z == pa.z) { // along X only (or not at all): one box
        const double r0 = std::min(L.r0, R.r0), r1 = std::max(L.r1, R.r1);
        lower_[0] = {L.z0, r0};
        lower_[1] = {L.z1, r0};
        upper_[0] = {L.z0, r1};
        upper_[1] = {L.z1, r1};
        nl_ = nu_ = 2;
    } else if (pb.r >= pa.r) {
        lower_[0] = {L.z0, L.r0};
        lower_[1] = {L.z1, L.r0};
        lower_[2] = {R.z1, R.r0};
        upper_[0] = {L.z0, L.r1};
        upper_[1] = {R.z0, R.r1};
        upper_[2] = {R.z1, R.r1};
        nl_ = nu_ = 3;
    } else {
        lower_[0] = {L.z0, L.r0};
        lower_[1] = {R.z0, R.r0};
        lower_[2] = {R.z1, R.r0};
        upper_[0] = {L.z0, L.r1};
        upper_[1] = {L.z1, L.r1};
        upper_[2] = {R.z1, R.r1};
        nl_ = nu_ = 3;
    }
    zMin_ = lower_[0].z;
    zMax_ = lower_[nl_ - 1].z;
    // Counter-clockwise: the lower chain, then the upper one backwards.
    for (std::size_t i = 0; i < nl_; ++i)
        v_[n_++] = lower_[i];
    for (std::size_t i = nu_; i-- > 0;)
        v_[n_++] = upper_[i];
    makePieces();
}

void Sweep::makePieces() {
    std::array<double, 16> zs{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < nl_; ++i)
        zs[n++] = lower_[i].z;
    for (std::size_t i = 0; i < nu_; ++i)
        zs[n++] = upper_[i].z;
    std::sort(zs.begin(), zs.begin() + static_cast<long>(n));
    std::size_t li = 0, ui = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const double a = zs[k], b = zs[k + 1];
        if (b <= a)
            continue;
        Piece p;
        p.z0 = a;
        p.z1 = b;
        const double la = chainAt(lower_, nl_, li, a), lb = chainAt(lower_, nl_, li, b);
        const double ha = chainAt(upper_, nu_, ui, a), hb = chainAt(upper_, nu_, ui, b);
        p.loB = (lb - la) / (b - a);
        p.loA = la - p.loB * a;
        p.hiB = (hb - ha) / (b - a);
        p.hiA = ha - p.hiB * a;
        pieces_[np_++] = p;
    }
    if (np_ == 0) { // no extent along Z: one vertical piece
        Piece p;
        p.z0 = p.z1 = zMin_;
        std::size_t i = 0, j = 0;
        p.loA = chainAt(lower_, nl_, i, zMin_);
        p.hiA = chainAt(upper_, nu_, j, zMin_);
        pieces_[np_++] = p;
    }
}

void Sweep::at(double z, double& lo, double& hi) {
    lo = chainAt(lower_, nl_, li_, z);
    hi = chainAt(upper_, nu_, ui_, z);
}

void Sweep::range(double za, double zb, double& loMin, double& hiMax) const {
    std::size_t i = 0, j = 0;
    loMin = std::min(chainAt(lower_, nl_, i, za), chainAt(lower_, nl_, i, zb));
    i = 0;
    hiMax = std::max(chainAt(upper_, nu_, j, za), chainAt(upper_, nu_, j, zb));
    for (std::size_t k = 0; k < nl_; ++k)
        if (lower_[k].z > za && lower_[k].z < zb)
            loMin = std::min(loMin, lower_[k].r);
    for (std::size_t k = 0; k < nu_; ++k)
        if (upper_[k].z > za && upper_[k].z < zb)
            hiMax = std::max(hiMax, upper_[k].r);
}

bool Sweep::overlaps(const Box& o, double eps) const {
    // Separating axes: the box's (z, r) and the hull's edge normals.
    if (zMax_ <= o.z0 + eps || zMin_ >= o.z1 - eps)
        return false;
    double rMin = v_[0].r, rMax = v_[0].r;
    for (std::size_t i = 1; i < n_; ++i) {
        rMin = std::min(rMin, v_[i].r);
        rMax = std::max(rMax, v_[i].r);
    }
    if (rMax <= o.r0 + eps || rMin >= o.r1 - eps)
        return false;
    const PointZR corners[4] = {{o.z0, o.r0}, {o.z1, o.r0}, {o.z1, o.r1}, {o.z0, o.r1}};
    for (std::size_t i = 0; i < n_; ++i) {
        const PointZR a = v_[i], b = v_[(i + 1) % n_];
        const double nz = b.r - a.r, nr = -(b.z - a.z); // outward normal of a CCW edge
        const double len = std::hypot(nz, nr);
        if (len == 0)
            continue;
        // The hull lies at projection <= a·n; the box is separated if all its
        // corners lie beyond.
        const double edge = (a.z * nz + a.r * nr) / len;
        double boxMin = 1e300;
        for (const PointZR& c : corners)
            boxMin = std::min(boxMin, (c.z * nz + c.r * nr) / len);
        if (boxMin >= edge - eps)
            return false;
    }
    return true;
}

} // namespace k528::proveout
