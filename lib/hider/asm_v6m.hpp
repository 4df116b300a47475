// Thumb-1 text shared by the naked ARMv6-M (Cortex-M0/M0+) assembly routines of raster/ and horizon/
// that use every register: HIDER_V6M_SAVE_ALL pushes r4-r11 and lr (ARMv6-M's push takes low registers
// only, so r8-r11 pass through r4-r7), and HIDER_V6M_RESTORE_ALL pops them and returns. The stack holds
// 36 bytes in between.
#pragma once

#define HIDER_V6M_SAVE_ALL \
    "push   {r4-r7, lr}\n\t" \
    "mov    r4, r8\n\t" \
    "mov    r5, r9\n\t" \
    "mov    r6, r10\n\t" \
    "mov    r7, r11\n\t" \
    "push   {r4-r7}\n\t"
#define HIDER_V6M_RESTORE_ALL \
    "pop    {r4-r7}\n\t" \
    "mov    r8, r4\n\t" \
    "mov    r9, r5\n\t" \
    "mov    r10, r6\n\t" \
    "mov    r11, r7\n\t" \
    "pop    {r4-r7, pc}\n"
