// Binary angles and the table sine/cosine against <cmath>: |error| <= 4 LSB of Q30 everywhere.
#include <hider/angle.hpp>

#include <cmath>
#include <random>

#include "support/fixed_print.hpp"

using hider::Angle;

namespace {
double exact_sin(uint32_t bam) { return std::sin(bam * (2.0 * M_PI / 4294967296.0)); }
}  // namespace

TEST_CASE("sin and cos are exact at the quadrant points") {
    CHECK(hider::sin(Angle::from_bam(0)).raw() == 0);
    CHECK(hider::sin(Angle::from_bam(0x40000000)).raw() == 1 << 30);
    CHECK(hider::sin(Angle::from_bam(0x80000000)).raw() == 0);
    CHECK(hider::sin(Angle::from_bam(0xC0000000)).raw() == -(1 << 30));
    CHECK(hider::cos(Angle::from_bam(0)).raw() == 1 << 30);
    CHECK(hider::cos(Angle::from_bam(0x80000000)).raw() == -(1 << 30));
}

TEST_CASE("sin and cos stay within 4 LSB of Q30 over the full turn") {
    int worst = 0;
    auto check = [&](uint32_t bam) {
        const double s = exact_sin(bam) * 1073741824.0;
        const double c = std::cos(bam * (2.0 * M_PI / 4294967296.0)) * 1073741824.0;
        const double es = std::fabs(hider::sin(Angle::from_bam(bam)).raw() - s);
        const double ec = std::fabs(hider::cos(Angle::from_bam(bam)).raw() - c);
        worst = std::max(worst, static_cast<int>(std::ceil(std::max(es, ec))));
        CHECK(es <= 4.0);
        CHECK(ec <= 4.0);
    };
    for (uint32_t i = 0; i < 65536; ++i) check(i << 16);              // every 1/65536 turn
    std::mt19937 rng(3);
    for (int i = 0; i < 65536; ++i) check(rng());                     // random angles
    for (uint32_t q = 0; q < 4; ++q)                                  // around every segment joint of a quarter
        for (uint32_t k = 0; k <= 256; ++k)
            for (int d = -2; d <= 2; ++d) check((q << 30) + (k << 22) + static_cast<uint32_t>(d));
    MESSAGE("worst sin/cos error: " << worst << " LSB of Q30");
}

TEST_CASE("Angle wraps and converts degrees to the nearest binary angle") {
    CHECK(Angle::from_degrees(hider::Q16::from_int(90)).bam() == 0x40000000u);
    CHECK(Angle::from_degrees(hider::Q16::from_int(-90)).bam() == 0xC0000000u);
    CHECK(Angle::from_degrees(hider::Q16::from_int(450)).bam() == 0x40000000u);
    CHECK((Angle::from_bam(0xF0000000u) + Angle::from_bam(0x20000000u)).bam() == 0x10000000u);
    const Angle a = Angle::from_degrees(hider::Q16::from_raw(static_cast<int32_t>(73.7398 * 65536)));
    CHECK(std::fabs(a.bam() / 4294967296.0 * 360.0 - 73.7398) < 1e-5);
}
