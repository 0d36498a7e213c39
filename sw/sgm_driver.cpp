// SPDX-License-Identifier: Apache-2.0
// sgm_driver.cpp: see sw/include/sgm_driver.hpp.
#include "sgm_driver.hpp"

namespace sgm::driver {

uint32_t Driver::encodeSize(uint32_t width, uint32_t height) {
  return SGM_PUT(FRAME_SIZE_WIDTH, width) | SGM_PUT(FRAME_SIZE_HEIGHT, height);
}

uint32_t Driver::encodePenalty(const FrameConfig& f) {
  return SGM_PUT(PENALTY_P1, f.p1) | SGM_PUT(PENALTY_P2, f.p2) | SGM_PUT(PENALTY_AD_CAP, f.adCap) |
         SGM_PUT(PENALTY_AD_WEIGHT, f.adWeight) | SGM_PUT(PENALTY_RIGHT_WEIGHT, f.rightWeight);
}

uint32_t Driver::encodeConfig(const FrameConfig& f) {
  return SGM_PUT(CONFIG_MODE, f.mode) | SGM_PUT(CONFIG_SUBPIXEL, f.subpixel) | SGM_PUT(CONFIG_LR_ENABLE, f.lrCheck) |
         SGM_PUT(CONFIG_LR_TOL, f.lrTolerance) | SGM_PUT(CONFIG_FILL, f.fill) | SGM_PUT(CONFIG_SNAP, f.snap) |
         SGM_PUT(CONFIG_MEDIAN, f.median) | SGM_PUT(CONFIG_P2_PAPER, f.p2Paper) |
         SGM_PUT(CONFIG_WEIGHTS_EQUAL, f.weightsEqual) | SGM_PUT(CONFIG_UNIQUENESS, f.uniqueness);
}

uint32_t Driver::encodeEdgeReset(const FrameConfig& f) {
  return SGM_PUT(EDGE_RESET_T, f.edgeReset) | SGM_PUT(EDGE_RESET_LEN, f.edgeResetLength) |
         SGM_PUT(EDGE_RESET_PATHS, f.edgeResetPaths);
}

uint32_t Driver::encodeOutput(const FrameConfig& f) {
  return SGM_PUT(OUTPUT_MODE, f.output) | SGM_PUT(OUTPUT_CONFIDENCE, f.confidence);
}
uint32_t Driver::encodeDepthFocal(const FrameConfig& f) { return SGM_PUT(DEPTH_FOCAL_F, f.focalQ8); }
uint32_t Driver::encodeDepthBaseline(const FrameConfig& f) { return SGM_PUT(DEPTH_BASELINE_B, f.baselineUm); }
uint32_t Driver::encodeMinDisparity(const FrameConfig& f) { return SGM_PUT(MIN_DISPARITY_DMIN, f.minDisparity); }
uint32_t Driver::encodeRectify(const FrameConfig& f) {
  return SGM_PUT(RECTIFY_ENABLE, f.rectify) | SGM_PUT(RECTIFY_LAG, f.rectifyLag);
}

bool Driver::sizeFits(const Identity& id, uint32_t width, uint32_t height) {
  return width >= id.minWidth && width <= id.maxWidth && height >= SGM_FRAME_SIZE_HEIGHT_MIN && height <= id.maxHeight;
}

bool Driver::featuresFit(const Identity& id, const FrameConfig& f) {
  return (f.uniqueness == 0 || (id.features & SGM_FEATURES_UNIQUENESS)) &&
         (f.adWeight == 0 || (id.features & SGM_FEATURES_AD_TERM)) &&
         (f.rightWeight == 0 || (id.features & SGM_FEATURES_RIGHT_PATH)) &&
         (f.edgeReset == 0 || (id.features & SGM_FEATURES_EDGE_RESET)) &&
         (f.output != SGM_OUTPUT_MODE_DEPTH || (id.features & SGM_FEATURES_DEPTH)) &&
         (f.minDisparity == 0 || (id.features & SGM_FEATURES_MIN_DISPARITY)) &&
         (!f.confidence || (id.features & SGM_FEATURES_CONFIDENCE)) &&
         ((!f.rectify && f.rectifyLag == 0) ||
          ((id.features & SGM_FEATURES_RECTIFY) && f.rectifyLag + 2 <= rectifyRows(id)));
}

uint32_t Driver::rectifyRows(const Identity& id) {
  return (id.features & SGM_FEATURES_RECTIFY) ? 1u << SGM_GET(id.features, FEATURES_RECTIFY_ROWS) : 0;
}

uint32_t Driver::rectifyGrid(const Identity& id) {
  return (id.features & SGM_FEATURES_RECTIFY) ? 1u << SGM_GET(id.features, FEATURES_RECTIFY_GRID) : 0;
}

uint32_t Driver::rightBlock(const Identity& id) {
  if (!(id.features & SGM_FEATURES_RIGHT_PATH)) return 0;
  return 1u << SGM_GET(id.features, FEATURES_RIGHT_BLOCK);
}

bool Driver::identify(Identity* id) {
  const uint32_t value = read(SGM_REG_ID);
  if (id) {
    id->version = SGM_GET(value, ID_VERSION);
    id->disparities = read(SGM_REG_D);
    id->maxWidth = read(SGM_REG_MAX_WIDTH);
    id->maxHeight = read(SGM_REG_MAX_HEIGHT);
    const uint32_t census = read(SGM_REG_CENSUS);
    id->censusWidth = SGM_GET(census, CENSUS_WIDTH);
    id->censusHeight = SGM_GET(census, CENSUS_HEIGHT);
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
  write(SGM_REG_OUTPUT, encodeOutput(f));
  write(SGM_REG_DEPTH_FOCAL, encodeDepthFocal(f));
  write(SGM_REG_DEPTH_BASELINE, encodeDepthBaseline(f));
  write(SGM_REG_MIN_DISPARITY, encodeMinDisparity(f));
  write(SGM_REG_RECTIFY, encodeRectify(f));
  write(SGM_REG_CTRL, ctrl & ~SGM_CTRL_HOLD);
}

FrameConfig Driver::readConfig() {
  const uint32_t size = read(SGM_REG_FRAME_SIZE), penalty = read(SGM_REG_PENALTY), config = read(SGM_REG_CONFIG);
  const uint32_t edge = read(SGM_REG_EDGE_RESET), output = read(SGM_REG_OUTPUT);
  const uint32_t focal = read(SGM_REG_DEPTH_FOCAL), baseline = read(SGM_REG_DEPTH_BASELINE);
  return decode(size, penalty, config, edge, output, focal, baseline, read(SGM_REG_MIN_DISPARITY),
                read(SGM_REG_RECTIFY));
}

FrameConfig Driver::decode(uint32_t size, uint32_t penalty, uint32_t config, uint32_t edge, uint32_t output,
                           uint32_t focal, uint32_t baseline, uint32_t minDisparity, uint32_t rectify) {
  FrameConfig f;
  f.width = SGM_GET(size, FRAME_SIZE_WIDTH);
  f.height = SGM_GET(size, FRAME_SIZE_HEIGHT);
  f.p1 = SGM_GET(penalty, PENALTY_P1);
  f.p2 = SGM_GET(penalty, PENALTY_P2);
  f.adCap = SGM_GET(penalty, PENALTY_AD_CAP);
  f.adWeight = SGM_GET(penalty, PENALTY_AD_WEIGHT);
  f.rightWeight = SGM_GET(penalty, PENALTY_RIGHT_WEIGHT);
  f.mode = SGM_GET(config, CONFIG_MODE);
  f.subpixel = SGM_GET(config, CONFIG_SUBPIXEL);
  f.lrCheck = SGM_GET(config, CONFIG_LR_ENABLE);
  f.lrTolerance = SGM_GET(config, CONFIG_LR_TOL);
  f.fill = SGM_GET(config, CONFIG_FILL);
  f.snap = SGM_GET(config, CONFIG_SNAP);
  f.median = SGM_GET(config, CONFIG_MEDIAN);
  f.p2Paper = SGM_GET(config, CONFIG_P2_PAPER);
  f.weightsEqual = SGM_GET(config, CONFIG_WEIGHTS_EQUAL);
  f.uniqueness = SGM_GET(config, CONFIG_UNIQUENESS);
  f.edgeReset = SGM_GET(edge, EDGE_RESET_T);
  f.edgeResetLength = SGM_GET(edge, EDGE_RESET_LEN);
  f.edgeResetPaths = SGM_GET(edge, EDGE_RESET_PATHS);
  f.output = SGM_GET(output, OUTPUT_MODE);
  f.confidence = SGM_GET(output, OUTPUT_CONFIDENCE);
  f.focalQ8 = SGM_GET(focal, DEPTH_FOCAL_F);
  f.baselineUm = SGM_GET(baseline, DEPTH_BASELINE_B);
  f.minDisparity = SGM_GET(minDisparity, MIN_DISPARITY_DMIN);
  f.rectify = SGM_GET(rectify, RECTIFY_ENABLE);
  f.rectifyLag = SGM_GET(rectify, RECTIFY_LAG);
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
  *width = SGM_GET(size, LAST_SIZE_WIDTH);
  *height = SGM_GET(size, LAST_SIZE_HEIGHT);
}

Errors Driver::errors() {
  Errors e;
  e.sticky = read(SGM_REG_ERROR) & SGM_ERROR_MASK;
  const uint32_t counts = read(SGM_REG_ERROR_COUNT);
  e.counts[0] = SGM_GET(counts, ERROR_COUNT_LAST_EARLY);
  e.counts[1] = SGM_GET(counts, ERROR_COUNT_LAST_MISSING);
  e.counts[2] = SGM_GET(counts, ERROR_COUNT_START_INSIDE);
  e.counts[3] = SGM_GET(counts, ERROR_COUNT_CONFIG);
  return e;
}

void Driver::clearErrors() {
  write(SGM_REG_ERROR, SGM_ERROR_MASK);
  write(SGM_REG_ERROR_COUNT, 0);
}

void Driver::enableInterrupts(uint32_t mask) { write(SGM_REG_IRQ_ENABLE, mask & SGM_IRQ_ENABLE_MASK); }

uint32_t Driver::interrupts() { return read(SGM_REG_IRQ_STATUS); }

void Driver::clearInterrupts(uint32_t mask) { write(SGM_REG_IRQ_STATUS, mask & SGM_IRQ_STATUS_MASK); }

bool Driver::meshSwapPending() { return SGM_GET(read(SGM_REG_MESH_CTRL), MESH_CTRL_PENDING); }

bool Driver::rectifyRowMiss() { return SGM_GET(read(SGM_REG_MESH_CTRL), MESH_CTRL_ROW_MISS); }

bool Driver::loadMeshes(const MeshImage& left, const MeshImage& right, long maxPolls) {
  for (const MeshImage* m : {&left, &right})
    if (m->nodesX == 0 || m->nodesY == 0 || m->nodesX > SGM_MESH_ADDR_COL_MAX + 1u ||
        m->nodesY > SGM_MESH_ADDR_ROW_MAX + 1u || !m->u || !m->v)
      return false;
  long polls = 0;
  while (meshSwapPending())
    if (++polls >= maxPolls) return false;
  for (uint32_t image = 0; image < 2; ++image) {
    const MeshImage& m = image ? right : left;
    for (uint32_t i = 0; i < m.nodesY; ++i) {
      // A row: its address once, then (u, v) per node (a write of MESH_V stores it and steps the column).
      write(SGM_REG_MESH_ADDR,
            SGM_PUT(MESH_ADDR_COL, 0u) | SGM_PUT(MESH_ADDR_ROW, i) | SGM_PUT(MESH_ADDR_RIGHT, image));
      for (uint32_t j = 0; j < m.nodesX; ++j) {
        const size_t k = size_t(i) * m.nodesX + j;
        write(SGM_REG_MESH_U, SGM_PUT(MESH_U_U, uint32_t(m.u[k])));
        write(SGM_REG_MESH_V, SGM_PUT(MESH_V_V, uint32_t(m.v[k])));
      }
    }
  }
  write(SGM_REG_MESH_CTRL, SGM_MESH_CTRL_SWAP);
  return true;
}

}  // namespace sgm::driver
