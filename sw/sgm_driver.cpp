// SPDX-License-Identifier: Apache-2.0
// sgm_driver.cpp: see sw/include/sgm_driver.hpp.
#include "sgm_driver.hpp"

namespace sgm::driver {

uint32_t Driver::encodeSize(uint32_t width, uint32_t height) {
  return (width & SGM_SIZE_FIELD_MASK) << SGM_SIZE_WIDTH_SHIFT | (height & SGM_SIZE_FIELD_MASK) << SGM_SIZE_HEIGHT_SHIFT;
}

uint32_t Driver::encodePenalty(const FrameConfig& f) {
  return (f.p1 & SGM_PENALTY_FIELD_MASK) << SGM_PENALTY_P1_SHIFT | (f.p2 & SGM_PENALTY_FIELD_MASK) << SGM_PENALTY_P2_SHIFT |
         (f.adCap & SGM_PENALTY_FIELD_MASK) << SGM_PENALTY_AD_CAP_SHIFT |
         (f.adWeight & SGM_PENALTY_AD_WEIGHT_MASK) << SGM_PENALTY_AD_WEIGHT_SHIFT |
         (f.rightWeight & SGM_PENALTY_RIGHT_WEIGHT_MASK) << SGM_PENALTY_RIGHT_WEIGHT_SHIFT;
}

uint32_t Driver::encodeConfig(const FrameConfig& f) {
  return (f.mode << SGM_CONFIG_MODE_SHIFT & SGM_CONFIG_MODE_MASK) | (f.subpixel ? SGM_CONFIG_SUBPIXEL : 0u) |
         (f.lrCheck ? SGM_CONFIG_LR_ENABLE : 0u) | (f.lrTolerance << SGM_CONFIG_LR_TOL_SHIFT & SGM_CONFIG_LR_TOL_MASK) |
         (f.fill ? SGM_CONFIG_FILL : 0u) | (f.snap ? SGM_CONFIG_SNAP : 0u) | (f.median ? SGM_CONFIG_MEDIAN : 0u) |
         (f.p2Paper ? SGM_CONFIG_P2_PAPER : 0u) | (f.weightsEqual ? SGM_CONFIG_WEIGHTS_EQUAL : 0u) |
         (f.uniqueness << SGM_CONFIG_UNIQUENESS_SHIFT & SGM_CONFIG_UNIQUENESS_MASK);
}

uint32_t Driver::encodeEdgeReset(const FrameConfig& f) {
  return (f.edgeReset & SGM_EDGE_RESET_T_MASK) << SGM_EDGE_RESET_T_SHIFT |
         (f.edgeResetLength & SGM_EDGE_RESET_LEN_MASK) << SGM_EDGE_RESET_LEN_SHIFT |
         (f.edgeResetPaths & SGM_EDGE_RESET_PATHS_MASK) << SGM_EDGE_RESET_PATHS_SHIFT;
}

bool Driver::sizeFits(const Identity& id, uint32_t width, uint32_t height) {
  return width >= id.minWidth && width <= id.maxWidth && height >= SGM_MIN_HEIGHT && height <= id.maxHeight;
}

bool Driver::featuresFit(const Identity& id, const FrameConfig& f) {
  return (f.uniqueness == 0 || (id.features & SGM_FEATURES_UNIQUENESS)) &&
         (f.adWeight == 0 || (id.features & SGM_FEATURES_AD_TERM)) &&
         (f.rightWeight == 0 || (id.features & SGM_FEATURES_RIGHT_PATH)) &&
         (f.edgeReset == 0 || (id.features & SGM_FEATURES_EDGE_RESET));
}

uint32_t Driver::rightBlock(const Identity& id) {
  if (!(id.features & SGM_FEATURES_RIGHT_PATH)) return 0;
  return 1u << (id.features >> SGM_FEATURES_RIGHT_BLOCK_SHIFT & SGM_FEATURES_RIGHT_BLOCK_MASK);
}

bool Driver::identify(Identity* id) {
  const uint32_t value = read(SGM_REG_ID);
  if (id) {
    id->version = value & SGM_ID_VERSION_MASK;
    id->disparities = read(SGM_REG_D);
    id->maxWidth = read(SGM_REG_MAX_WIDTH);
    id->maxHeight = read(SGM_REG_MAX_HEIGHT);
    const uint32_t census = read(SGM_REG_CENSUS);
    id->censusWidth = census >> SGM_CENSUS_WIDTH_SHIFT & SGM_CENSUS_FIELD_MASK;
    id->censusHeight = census >> SGM_CENSUS_HEIGHT_SHIFT & SGM_CENSUS_FIELD_MASK;
    id->minWidth = read(SGM_REG_MIN_WIDTH);
    id->lanes = read(SGM_REG_LANES);
    id->features = read(SGM_REG_FEATURES);
  }
  return value == SGM_ID_VALUE;
}

void Driver::configure(const FrameConfig& f) {
  const uint32_t ctrl = read(SGM_REG_CTRL) & SGM_CTRL_MASK;
  write(SGM_REG_CTRL, ctrl | SGM_CTRL_HOLD);
  write(SGM_REG_FRAME_SIZE, encodeSize(f.width, f.height));
  write(SGM_REG_PENALTY, encodePenalty(f));
  write(SGM_REG_CONFIG, encodeConfig(f));
  write(SGM_REG_EDGE_RESET, encodeEdgeReset(f));
  write(SGM_REG_CTRL, ctrl & ~SGM_CTRL_HOLD);
}

FrameConfig Driver::readConfig() {
  FrameConfig f;
  const uint32_t size = read(SGM_REG_FRAME_SIZE), penalty = read(SGM_REG_PENALTY), config = read(SGM_REG_CONFIG);
  f.width = size >> SGM_SIZE_WIDTH_SHIFT & SGM_SIZE_FIELD_MASK;
  f.height = size >> SGM_SIZE_HEIGHT_SHIFT & SGM_SIZE_FIELD_MASK;
  f.p1 = penalty >> SGM_PENALTY_P1_SHIFT & SGM_PENALTY_FIELD_MASK;
  f.p2 = penalty >> SGM_PENALTY_P2_SHIFT & SGM_PENALTY_FIELD_MASK;
  f.adCap = penalty >> SGM_PENALTY_AD_CAP_SHIFT & SGM_PENALTY_FIELD_MASK;
  f.adWeight = penalty >> SGM_PENALTY_AD_WEIGHT_SHIFT & SGM_PENALTY_AD_WEIGHT_MASK;
  f.rightWeight = penalty >> SGM_PENALTY_RIGHT_WEIGHT_SHIFT & SGM_PENALTY_RIGHT_WEIGHT_MASK;
  f.mode = (config & SGM_CONFIG_MODE_MASK) >> SGM_CONFIG_MODE_SHIFT;
  f.subpixel = config & SGM_CONFIG_SUBPIXEL;
  f.lrCheck = config & SGM_CONFIG_LR_ENABLE;
  f.lrTolerance = (config & SGM_CONFIG_LR_TOL_MASK) >> SGM_CONFIG_LR_TOL_SHIFT;
  f.fill = config & SGM_CONFIG_FILL;
  f.snap = config & SGM_CONFIG_SNAP;
  f.median = config & SGM_CONFIG_MEDIAN;
  f.p2Paper = config & SGM_CONFIG_P2_PAPER;
  f.weightsEqual = config & SGM_CONFIG_WEIGHTS_EQUAL;
  f.uniqueness = (config & SGM_CONFIG_UNIQUENESS_MASK) >> SGM_CONFIG_UNIQUENESS_SHIFT;
  const uint32_t edge = read(SGM_REG_EDGE_RESET);
  f.edgeReset = edge >> SGM_EDGE_RESET_T_SHIFT & SGM_EDGE_RESET_T_MASK;
  f.edgeResetLength = edge >> SGM_EDGE_RESET_LEN_SHIFT & SGM_EDGE_RESET_LEN_MASK;
  f.edgeResetPaths = edge >> SGM_EDGE_RESET_PATHS_SHIFT & SGM_EDGE_RESET_PATHS_MASK;
  return f;
}

void Driver::enable(bool on) {
  const uint32_t ctrl = read(SGM_REG_CTRL) & SGM_CTRL_MASK;
  write(SGM_REG_CTRL, on ? ctrl | SGM_CTRL_ENABLE : ctrl & ~SGM_CTRL_ENABLE);
}

bool Driver::softReset(long maxPolls) {
  write(SGM_REG_CTRL, (read(SGM_REG_CTRL) & SGM_CTRL_MASK) | SGM_CTRL_SOFT_RESET);
  for (long i = 0; i < maxPolls; ++i)
    if (!(read(SGM_REG_STATUS) & SGM_STATUS_RESETTING)) return true;
  return false;
}

bool Driver::busy() { return read(SGM_REG_STATUS) & SGM_STATUS_BUSY; }

uint32_t Driver::framesDone() { return read(SGM_REG_FRAMES); }

bool Driver::waitFrames(uint32_t target, long maxPolls) {
  for (long i = 0; i < maxPolls; ++i)
    if (int32_t(read(SGM_REG_FRAMES) - target) >= 0) return true;
  return false;
}

void Driver::lastFrameSize(uint32_t* width, uint32_t* height) {
  const uint32_t size = read(SGM_REG_LAST_SIZE);
  *width = size >> SGM_SIZE_WIDTH_SHIFT & SGM_SIZE_FIELD_MASK;
  *height = size >> SGM_SIZE_HEIGHT_SHIFT & SGM_SIZE_FIELD_MASK;
}

Errors Driver::errors() {
  Errors e;
  e.sticky = read(SGM_REG_ERROR) & SGM_ERROR_MASK;
  const uint32_t counts = read(SGM_REG_ERROR_COUNT);
  for (int k = 0; k < SGM_ERROR_KINDS; ++k) e.counts[k] = counts >> (8 * k) & 0xFFu;
  return e;
}

void Driver::clearErrors() {
  write(SGM_REG_ERROR, SGM_ERROR_MASK);
  write(SGM_REG_ERROR_COUNT, 0);
}

void Driver::enableInterrupts(uint32_t mask) { write(SGM_REG_IRQ_ENABLE, mask & SGM_IRQ_MASK); }

uint32_t Driver::interrupts() { return read(SGM_REG_IRQ_STATUS); }

void Driver::clearInterrupts(uint32_t mask) { write(SGM_REG_IRQ_STATUS, mask & SGM_IRQ_MASK); }

}  // namespace sgm::driver
