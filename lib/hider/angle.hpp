// Wrapping binary angles (2^32 units per turn, so overflow is rotation) and their sine and cosine
// from a 257-entry quarter-wave table with cubic Hermite interpolation (slopes from the same table).
// Accuracy: |error| <= 4 LSB of Q30 (~3.7e-9) for every angle (tested against <cmath> in tests/angle_test.cpp).
#pragma once
#include <hider/fixed.hpp>

namespace hider {

/// Angle as an unsigned binary fraction of a full turn: 0x40000000 = 90 degrees. Arithmetic wraps.
class Angle {
public:
    static constexpr uint32_t kQuarter = uint32_t{1} << 30;

    constexpr Angle() = default;
    static constexpr Angle from_bam(uint32_t bam) { Angle a; a.bam_ = bam; return a; }
    /// Degrees in Q16.16 to the nearest binary angle (any sign; wraps).
    static constexpr Angle from_degrees(Q16 degrees) {
        const int64_t bam = div_round(int64_t{degrees.raw()} * 65536, 360);
        return from_bam(static_cast<uint32_t>(static_cast<uint64_t>(bam)));
    }
    constexpr uint32_t bam() const { return bam_; }

    friend constexpr Angle operator+(Angle a, Angle b) { return from_bam(a.bam_ + b.bam_); }
    friend constexpr Angle operator-(Angle a, Angle b) { return from_bam(a.bam_ - b.bam_); }
    friend constexpr bool operator==(Angle a, Angle b) { return a.bam_ == b.bam_; }
    friend constexpr bool operator!=(Angle a, Angle b) { return a.bam_ != b.bam_; }

private:
    uint32_t bam_ = 0;
};

namespace detail {
/// sin(i * pi / 512) in Q30 for i = 0..256 (a quarter wave), rounded to nearest.
constexpr int32_t kSinTable[257] = {
    0, 6588356, 13176464, 19764076, 26350943, 32936819, 39521455, 46104602,
    52686014, 59265442, 65842639, 72417357, 78989349, 85558366, 92124163, 98686491,
    105245103, 111799753, 118350194, 124896179, 131437462, 137973796, 144504935, 151030634,
    157550647, 164064728, 170572633, 177074115, 183568930, 190056834, 196537583, 203010932,
    209476638, 215934457, 222384147, 228825464, 235258165, 241682010, 248096755, 254502159,
    260897982, 267283981, 273659918, 280025552, 286380643, 292724951, 299058239, 305380268,
    311690799, 317989595, 324276419, 330551034, 336813204, 343062693, 349299266, 355522689,
    361732726, 367929144, 374111709, 380280190, 386434353, 392573967, 398698801, 404808624,
    410903207, 416982319, 423045732, 429093217, 435124548, 441139496, 447137835, 453119340,
    459083786, 465030947, 470960600, 476872522, 482766489, 488642281, 494499676, 500338453,
    506158392, 511959275, 517740883, 523502998, 529245404, 534967884, 540670223, 546352205,
    552013618, 557654248, 563273883, 568872310, 574449320, 580004702, 585538248, 591049748,
    596538995, 602005783, 607449906, 612871159, 618269338, 623644239, 628995660, 634323400,
    639627258, 644907034, 650162530, 655393548, 660599890, 665781362, 670937767, 676068911,
    681174602, 686254647, 691308855, 696337036, 701339000, 706314559, 711263525, 716185713,
    721080937, 725949013, 730789757, 735602987, 740388522, 745146182, 749875788, 754577161,
    759250125, 763894504, 768510122, 773096806, 777654384, 782182683, 786681534, 791150767,
    795590213, 799999706, 804379079, 808728167, 813046808, 817334838, 821592095, 825818421,
    830013654, 834177638, 838310216, 842411232, 846480531, 850517961, 854523370, 858496606,
    862437520, 866345964, 870221790, 874064853, 877875009, 881652112, 885396022, 889106597,
    892783698, 896427186, 900036924, 903612776, 907154608, 910662286, 914135678, 917574653,
    920979082, 924348837, 927683790, 930983817, 934248793, 937478595, 940673101, 943832191,
    946955747, 950043650, 953095785, 956112036, 959092290, 962036435, 964944360, 967815955,
    970651112, 973449725, 976211688, 978936898, 981625251, 984276646, 986890984, 989468165,
    992008094, 994510675, 996975812, 999403415, 1001793390, 1004145648, 1006460100, 1008736660,
    1010975242, 1013175761, 1015338134, 1017462281, 1019548121, 1021595575, 1023604567, 1025575020,
    1027506862, 1029400018, 1031254418, 1033069992, 1034846671, 1036584389, 1038283080, 1039942680,
    1041563127, 1043144360, 1044686319, 1046188946, 1047652185, 1049075980, 1050460278, 1051805027,
    1053110176, 1054375676, 1055601479, 1056787540, 1057933813, 1059040255, 1060106826, 1061133483,
    1062120190, 1063066909, 1063973603, 1064840240, 1065666786, 1066453210, 1067199483, 1067905576,
    1068571464, 1069197120, 1069782521, 1070327646, 1070832474, 1071296985, 1071721163, 1072104991,
    1072448455, 1072751542, 1073014240, 1073236540, 1073418433, 1073559913, 1073660973, 1073721611,
    1073741824
};
constexpr int32_t kSegmentQ30 = 6588397;  // pi / 512 in Q30: the table step in radians

/// sin of r * (pi/2) / 2^30 for r in [0, 2^30], Q30.
constexpr int32_t sin_quarter(uint32_t r) {
    const uint32_t i = r >> 22;
    if (i >= 256) return kSinTable[256];
    const int64_t t = int64_t{static_cast<int32_t>(r & 0x3FFFFF)} << 8;  // position in segment, Q30
    const int64_t p0 = kSinTable[i];
    const int64_t p1 = kSinTable[i + 1];
    const int64_t m0 = (int64_t{kSinTable[256 - i]} * kSegmentQ30) >> 30;  // d/dt = step * cos
    const int64_t m1 = (int64_t{kSinTable[255 - i]} * kSegmentQ30) >> 30;
    const int64_t c2 = 3 * (p1 - p0) - 2 * m0 - m1;  // Hermite cubic p0 + m0 t + c2 t^2 + c3 t^3
    const int64_t c3 = 2 * (p0 - p1) + m0 + m1;
    const int64_t inner = c2 + ((t * c3) >> 30);
    const int64_t mid = m0 + ((t * inner) >> 30);
    return static_cast<int32_t>(p0 + ((t * mid + (int64_t{1} << 29)) >> 30));
}
}  // namespace detail

/// sine in Q30 (1.0 = 2^30); |error| <= 4 LSB.
constexpr Q30 sin(Angle a) {
    const uint32_t r = a.bam() & (Angle::kQuarter - 1);
    switch (a.bam() >> 30) {
        case 0: return Q30::from_raw(detail::sin_quarter(r));
        case 1: return Q30::from_raw(detail::sin_quarter(Angle::kQuarter - r));
        case 2: return Q30::from_raw(-detail::sin_quarter(r));
        default: return Q30::from_raw(-detail::sin_quarter(Angle::kQuarter - r));
    }
}

/// cosine in Q30; |error| <= 4 LSB.
constexpr Q30 cos(Angle a) { return sin(a + Angle::from_bam(Angle::kQuarter)); }

}  // namespace hider
