// SPDX-License-Identifier: Apache-2.0
#include "sgm/pipeline.hpp"

#include "sgm/aggregate.hpp"
#include "sgm/census.hpp"
#include "sgm/cost.hpp"
#include "sgm/disparity.hpp"

namespace sgm {

namespace {

// Section 3, the minimum disparity: C(x, d) of the search dmin .. dmin + D - 1 is the cost at
// dmin + d of a search over dmin + D disparities (wide holds that row, W x (dmin + D)).
void keepFromMinDisparity(const uint8_t* wide, int x0, int x1, int nd, int dmin, uint8_t* row) {
  for (int x = x0; x < x1; ++x) std::copy_n(wide + size_t(x) * (nd + dmin) + dmin, nd, row + size_t(x) * nd);
}

}  // namespace

void checkInput(const cv::Mat& gl, const cv::Mat& gr, const Params& params) {
  params.validate();
  if (gl.type() != CV_8UC1 || gr.type() != CV_8UC1) throw Error("internal: pipeline needs 8-bit gray images");
  if (gl.size() != gr.size())
    throw Error("left/right size mismatch: " + std::to_string(gl.cols) + "x" + std::to_string(gl.rows) + " vs " +
                std::to_string(gr.cols) + "x" + std::to_string(gr.rows));
  if (gl.cols < kMinFrameSide || gl.rows < kMinFrameSide)
    throw Error("image " + std::to_string(gl.cols) + "x" + std::to_string(gl.rows) + " is smaller than the " +
                std::to_string(kMinFrameSide) + "x" + std::to_string(kMinFrameSide) + " minimum frame");
}

PipelineStages runPipelineStages(const cv::Mat& gl, const cv::Mat& gr, const Params& params) {
  checkInput(gl, gr, params);
  PipelineStages st;
  const int searched = params.minDisparity + params.disparities;
  CostVolume wide = computeCost(gl, gr, params.mode, searched, params.census);
  if (params.adWeight)
    for (int y = 0; y < gl.rows; ++y)
      addAdTerm(gl, gr, y, 0, gl.cols, searched, params.adWeight, params.adCap, wide.at(0, y));
  if (params.minDisparity) {
    st.cost = CostVolume(gl.cols, gl.rows, params.disparities);
    for (int y = 0; y < gl.rows; ++y)
      keepFromMinDisparity(wide.at(0, y), 0, gl.cols, params.disparities, params.minDisparity, st.cost.at(0, y));
  } else {
    st.cost = std::move(wide);
  }
  st.aggregated = aggregateCost(st.cost, gl, params.p1, params.p2, params.p2Mode, params.weights,
                                params.rightPathWeight, params.mgm, params.rightPathBlock, params.p1PathPercent.data(),
                                params.edgeReset, params.lrStoreBits);
  st.selected = selectDisparity(st.aggregated, params, &st.confidence);
  st.selected.confidence = st.confidence;
  st.filled = params.fill ? fillHoles(st.selected) : st.selected;
  st.snapped = params.snap ? snapEdges(st.filled, gl, params.snapEdge) : st.filled;
  st.result = params.median ? median5x5(st.snapped, gl, params.medianGate) : st.snapped;
  return st;
}

DisparityMap runPipeline(const cv::Mat& gl, const cv::Mat& gr, const Params& params, cv::Mat* confidence) {
  checkInput(gl, gr, params);
  const int w = gl.cols, h = gl.rows, nd = params.disparities;
  // Hardware modes stream C from the census images row by row; the software
  // modes read rows of a precomputed volume.
  std::vector<Census> censusLeft, censusRight;
  CostVolume volume;
  CostRowFn costRow;
  const int dmin = params.minDisparity, searched = dmin + nd;
  if (isHardwareMode(params.mode)) {
    censusLeft = censusTransform(gl, params.census);
    censusRight = censusTransform(gr, params.census);
    costRow = [&](int y, int x0, int x1, uint8_t* row) {
      thread_local std::vector<uint8_t> wide;
      uint8_t* out = row;
      if (dmin) wide.resize(size_t(w) * searched), out = wide.data();
      censusCostRow(params.mode, params.census, &censusLeft[size_t(y) * w], &censusRight[size_t(y) * w], w, x0, x1,
                    searched, out);
      if (params.adWeight) addAdTerm(gl, gr, y, x0, x1, searched, params.adWeight, params.adCap, out);
      if (dmin) keepFromMinDisparity(out, x0, x1, nd, dmin, row);
    };
  } else {
    volume = computeCost(gl, gr, params.mode, searched, params.census);
    costRow = [&](int y, int x0, int x1, uint8_t* row) {
      keepFromMinDisparity(volume.at(0, y), x0, x1, nd, dmin, row);
    };
  }
  DisparityMap selected{cv::Mat(h, w, CV_16UC1), cv::Mat(h, w, CV_8UC1)};
  if (confidence || params.outputConfidence) selected.confidence.create(h, w, CV_8UC1);
  const bool withConfidence = !selected.confidence.empty();
  RowSelector selectors[2] = {RowSelector(w, nd, params), RowSelector(w, nd, params)};  // one per worker
  aggregateRows(
      w, h, nd, gl, params.p1, params.p2, params.p2Mode, params.weights, costRow,
      [&](int worker, int y, const uint16_t* sum) {
        selectors[worker].select(sum, selected.disp.ptr<uint16_t>(y), selected.valid.ptr<uint8_t>(y),
                                 withConfidence ? selected.confidence.ptr<uint8_t>(y) : nullptr);
      },
      params.rightPathWeight, params.mgm, params.rightPathBlock, params.p1PathPercent.data(), params.edgeReset,
      params.lrStoreBits);
  const DisparityMap filled = params.fill ? fillHoles(selected) : selected;
  const DisparityMap snapped = params.snap ? snapEdges(filled, gl, params.snapEdge) : filled;
  if (confidence) *confidence = selected.confidence;
  return params.median ? median5x5(snapped, gl, params.medianGate) : snapped;
}

DisparityMap runRectifiedPipeline(const cv::Mat& rawLeft, const cv::Mat& rawRight, const StereoMesh& mesh,
                                  const Params& params, RectifiedPair* rectified, cv::Mat* confidence) {
  checkInput(rawLeft, rawRight, params);
  if (rawLeft.cols != mesh.left.width || rawLeft.rows != mesh.left.height)
    throw Error("the calibration is for " + std::to_string(mesh.left.width) + "x" + std::to_string(mesh.left.height) +
                " frames, the pair is " + std::to_string(rawLeft.cols) + "x" + std::to_string(rawLeft.rows));
  RectifiedPair pair{rectify(rawLeft, mesh.left), rectify(rawRight, mesh.right)};
  DisparityMap map = runPipeline(pair.left.gray, pair.right.gray, params, confidence);
  const cv::Mat outside = pair.left.valid == 0;
  map.disp.setTo(0, outside), map.valid.setTo(0, outside);
  if (!map.confidence.empty()) map.confidence.setTo(0, outside);  // also *confidence: the same pixels
  if (rectified) *rectified = std::move(pair);
  return map;
}

}  // namespace sgm
