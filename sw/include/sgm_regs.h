/* SPDX-License-Identifier: Apache-2.0 */
/* sgm_regs.h: the register map of sgm_axi (rtl/sgm_axi.sv), the one machine
 * source of the offsets, fields and reset values: the driver (sw/) and the
 * tests use it, and tests/rtl/test_sgm_axi.cpp checks the RTL's localparams
 * against it. docs/registers.md is the prose version.
 *
 * All registers are 32 bits wide, at byte offsets from the slave's base.
 * Bits not named here are reserved: they read 0 and ignore writes.
 * Undefined offsets answer SLVERR (reads return 0, writes are ignored).
 * Plain C (C89 and C++); no dependency. */
#ifndef SGM_REGS_H
#define SGM_REGS_H

/* ---- identification (read-only) */
#define SGM_REG_ID              0x00u /* SGM_ID_VALUE: "SGM" and the map version */
#define SGM_REG_D               0x04u /* D, disparities of the build */
#define SGM_REG_MAX_WIDTH       0x08u /* MAX_WIDTH of the build */
#define SGM_REG_MAX_HEIGHT      0x0Cu /* MAX_HEIGHT of the build */
#define SGM_REG_CENSUS          0x10u /* census window: [7:0] width, [15:8] height */
#define SGM_REG_MIN_WIDTH       0x14u /* narrowest frame width of the build (map version 2) */
#define SGM_REG_LANES           0x18u /* row lanes of the build, LANES (map version 2) */
#define SGM_REG_FEATURES        0x1Cu /* the run-time levers the build has, SGM_FEATURES_* (map version 4; bit 3 version 5) */

/* ---- control (read-write) */
#define SGM_REG_CTRL            0x20u
#define SGM_REG_FRAME_SIZE      0x24u /* [15:0] width, [31:16] height of the next frames */
#define SGM_REG_PENALTY         0x28u /* [7:0] P1, [15:8] P2', [23:16] AD cap, [27:24] AD weight */
#define SGM_REG_CONFIG          0x2Cu /* cost mode and stages */

/* ---- status (read-only, except the write-1-to-clear / clear-on-write ones) */
#define SGM_REG_STATUS          0x30u
#define SGM_REG_FRAMES          0x34u /* frames finished since reset (wraps) */
#define SGM_REG_ERROR           0x38u /* sticky error kinds, write 1 to clear */
#define SGM_REG_ERROR_COUNT     0x3Cu /* byte k: events of error kind k (saturating at 255);
                                         a write clears the counters of its enabled byte lanes */
#define SGM_REG_LAST_SIZE       0x40u /* [15:0] width, [31:16] height of the last finished frame */

/* ---- control (read-write), map version 5 */
#define SGM_REG_EDGE_RESET      0x44u /* the path restart at strong edges: [7:0] T, [11:8] R, [20:16] path flags */

/* ---- interrupt */
#define SGM_REG_IRQ_ENABLE      0x48u
#define SGM_REG_IRQ_STATUS      0x4Cu /* write 1 to clear; irq_o = |(IRQ_STATUS & IRQ_ENABLE) */

/* ---- values and fields */
#define SGM_ID_VALUE            0x53474D05u /* 'S' 'G' 'M', version 5 (4 had no EDGE_RESET, 3 no FEATURES,
                                               2 no CONFIG.UNIQUENESS, 1 no MIN_WIDTH, LANES) */
#define SGM_MIN_HEIGHT          9u /* shortest frame of every build (sgm_stream_ctrl) */
#define SGM_ID_MAGIC_MASK       0xFFFFFF00u
#define SGM_ID_VERSION_MASK     0x000000FFu

#define SGM_CENSUS_WIDTH_SHIFT  0
#define SGM_CENSUS_HEIGHT_SHIFT 8
#define SGM_CENSUS_FIELD_MASK   0xFFu

/* FEATURES: 1 = the build has the lever (sgm_top UNIQUENESS / AD_TERM / RIGHT_BLOCK /
 * EDGE_RESET); a frame that sets a lever the build lacks (CONFIG.UNIQUENESS,
 * PENALTY.AD_WEIGHT, PENALTY.RIGHT_WEIGHT or EDGE_RESET.T not 0) is dropped with
 * ERROR.CONFIG. Other bits are reserved (read 0). */
#define SGM_FEATURES_UNIQUENESS (1u << 0) /* the uniqueness ratio (CONFIG.UNIQUENESS) */
#define SGM_FEATURES_AD_TERM    (1u << 1) /* the AD term (PENALTY.AD_WEIGHT, AD_CAP) */
#define SGM_FEATURES_RIGHT_PATH (1u << 2) /* the fifth path in blocks (PENALTY.RIGHT_WEIGHT) */
#define SGM_FEATURES_EDGE_RESET (1u << 3) /* the path restart at strong edges (EDGE_RESET; map version 5) */
#define SGM_FEATURES_RIGHT_BLOCK_SHIFT 8  /* 4 bits: log2 of the fifth path's block B (0 without it) */
#define SGM_FEATURES_RIGHT_BLOCK_MASK  0xFu
#define SGM_FEATURES_MASK       0x00000F0Fu

#define SGM_CTRL_ENABLE         (1u << 0) /* 0: a start-of-frame beat is held back (frame boundary) */
#define SGM_CTRL_SOFT_RESET     (1u << 1) /* write 1: reset the core (not the registers); reads 0 */
#define SGM_CTRL_HOLD           (1u << 2) /* 1: the core keeps the configuration released last */
#define SGM_CTRL_MASK           0x00000005u /* the bits that read back */

#define SGM_SIZE_WIDTH_SHIFT    0
#define SGM_SIZE_HEIGHT_SHIFT   16
#define SGM_SIZE_FIELD_MASK     0xFFFFu

#define SGM_PENALTY_P1_SHIFT    0
#define SGM_PENALTY_P2_SHIFT    8
#define SGM_PENALTY_FIELD_MASK  0xFFu
#define SGM_PENALTY_AD_CAP_SHIFT    16     /* 8 bits: the AD term's cap T (gray levels) */
#define SGM_PENALTY_AD_WEIGHT_SHIFT 24     /* 4 bits: the AD term's weight W, 0 off; C += (W min(AD, T)) >> 3 */
#define SGM_PENALTY_AD_WEIGHT_MASK  0xFu
#define SGM_PENALTY_RIGHT_WEIGHT_SHIFT 28  /* 4 bits: the fifth path's weight W5, 0 off, 1 .. 8; S += W5 L5 */
#define SGM_PENALTY_RIGHT_WEIGHT_MASK  0xFu
#define SGM_PENALTY_MASK        0xFFFFFFFFu

#define SGM_CONFIG_MODE_SHIFT   0          /* 2 bits */
#define SGM_CONFIG_MODE_MASK    (3u << 0)
#define SGM_MODE_RT             0u
#define SGM_MODE_RSAD           1u
#define SGM_MODE_UNIFIED        2u         /* 3 also means unified */
#define SGM_CONFIG_SUBPIXEL     (1u << 4)
#define SGM_CONFIG_LR_ENABLE    (1u << 5)
#define SGM_CONFIG_LR_TOL_SHIFT 8          /* 3 bits: tolerance in px */
#define SGM_CONFIG_LR_TOL_MASK  (7u << 8)
#define SGM_CONFIG_FILL         (1u << 12)
#define SGM_CONFIG_SNAP         (1u << 13)
#define SGM_CONFIG_MEDIAN       (1u << 14)
#define SGM_CONFIG_P2_PAPER     (1u << 16) /* P2 adaptation: 0 knee max(P1, 4 P2'/(dI + 4)), 1 the paper's max(P1, P2'/dI) */
#define SGM_CONFIG_WEIGHTS_EQUAL (1u << 17) /* path weights in S: 0 = 3,2,3,2, 1 = equal (the paper) */
#define SGM_CONFIG_UNIQUENESS_SHIFT 24     /* 7 bits: uniqueness ratio in %, 0 off, 1 .. 99 (100 .. 127: frame dropped, ERROR.CONFIG) */
#define SGM_CONFIG_UNIQUENESS_MASK  (0x7Fu << 24)
#define SGM_CONFIG_UNIQUENESS_MAX   99u
#define SGM_CONFIG_MASK         0x7F037733u

/* EDGE_RESET: a path marked in PATHS starts again (Lr = C) at every pixel whose last R steps
 * along the path cross a gray step of at least T (docs/algorithm.md section 12). T = 0: off;
 * T != 0 with R = 0, or without SGM_FEATURES_EDGE_RESET: frame dropped, ERROR.CONFIG. */
#define SGM_EDGE_RESET_T_SHIFT      0      /* 8 bits: the gray step of a strong edge, 0 off */
#define SGM_EDGE_RESET_T_MASK       0xFFu
#define SGM_EDGE_RESET_LEN_SHIFT    8      /* 4 bits: R, steps restarted from the edge on, 1 .. 15 */
#define SGM_EDGE_RESET_LEN_MASK     0xFu
#define SGM_EDGE_RESET_PATHS_SHIFT  16     /* 5 bits: bit k = path k restarts (0, 45, 90, 135 degrees, the fifth) */
#define SGM_EDGE_RESET_PATHS_MASK   0x1Fu
#define SGM_EDGE_RESET_MASK         0x001F0FFFu

#define SGM_STATUS_BUSY         (1u << 0) /* a frame is in flight */
#define SGM_STATUS_RESETTING    (1u << 1) /* the soft reset is running */

#define SGM_ERROR_LAST_EARLY    (1u << 0) /* tlast before the last column */
#define SGM_ERROR_LAST_MISSING  (1u << 1) /* no tlast at the last column */
#define SGM_ERROR_START_INSIDE  (1u << 2) /* tuser inside a frame */
#define SGM_ERROR_CONFIG        (1u << 3) /* configuration out of range (size, P2' < P1, mode 3, uniqueness,
                                             AD term, a lever FEATURES lacks): frame dropped */
#define SGM_ERROR_MASK          0x0000000Fu
#define SGM_ERROR_KINDS         4

#define SGM_IRQ_FRAME_DONE      (1u << 0)
#define SGM_IRQ_ERROR           (1u << 1)
#define SGM_IRQ_MASK            0x00000003u

/* ---- reset values (every other register resets to 0) */
/* A build with the fifth path, the uniqueness ratio, the AD term and the path restart (FEATURES) resets to
   the golden model's defaults, any other build to its "four-path" preset. */
#define SGM_PENALTY_RESET       0x4314C818u /* P1 24, P2' 200, AD cap 20, AD weight 3, W5 4 */
#define SGM_CONFIG_RESET        0x0F005131u /* rsad, sub-pixel, LR check tolerance 1, fill, median, uniqueness 15 */
#define SGM_PENALTY_RESET_FOUR_PATH 0x00146412u /* P1 18, P2' 100, AD cap 20, AD weight 0 (off), W5 0 (off) */
#define SGM_CONFIG_RESET_FOUR_PATH  0x00007131u /* rsad, sub-pixel, LR check tolerance 1, fill, snap, median */
#define SGM_EDGE_RESET_RESET    0x001B0628u /* T 40, R 6, paths 0, 45, 135 degrees and the fifth */
#define SGM_EDGE_RESET_RESET_FOUR_PATH 0x001F0500u /* off (T 0), R 5, every path: the golden EdgeReset{} */

#endif /* SGM_REGS_H */
