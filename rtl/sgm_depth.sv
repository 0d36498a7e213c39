// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_depth: the core's output word (docs/algorithm.md sections 10 and 10b). In disparity
// mode (depth_en_i = 0) the word is {valid, zeros, disparity x 16}; in depth mode it is
// the depth in millimetres,
//
//   Z = min(65535, max(1, floor((K + 8000 dq) / (16000 dq))))   K = F B, dq = disparity x 16
//
// 0 for an invalid pixel, 65535 for dq = 0: exactly the golden model's integer definition
// (golden/sgm/depth.hpp), so the word is bit-exact, not an approximation.
//
// K = focal_i x baseline_i (24 x 24 bits, constants of the frame) is made by a shift-add
// multiplier (one step per cycle, at most 24 cycles) that starts at start_i, the pulse
// of the frame's configuration being latched (sgm_stream_ctrl's lut_start_o);
// ready_o is ready_i (the P2 table's) and not while it runs: the core holds the frame's
// first slot until it is high, so every pixel of the frame sees its K.
// The division is restoring, one quotient bit per pipeline stage: V = 16000 dq has
// VW = DW + 14 bits, N = K + 8000 dq 49; first the saturation (N >= V 2^16, that is
// floor(N / 2^16) >= V, which holds for dq = 0 too), then for bit i = 15 .. 0 the remainder, below
// V 2^(i+1), is compared with V 2^i on its top VW + 1 bits only (a VW + 1-bit
// subtraction per stage, not a 49-bit one).
//
// Parameters: DW disparity bits (4 fractional; 5 .. 15); LATENCY the latency its user
// expects (must be 20: the module checks its user's pipeline, as sgm_top waits the
// confidence for the depth word).
// Latency: LATENCY = 20 slots (input registers, N and V, the saturation, 16 quotient
// bits, the word) in both modes. Throughput: one pixel per enabled slot (en_i).
// Cost (Yosys 0.23, DW = 10, synth_ecp5): docs/notes/synthesis-log.md.
module sgm_depth #(
  parameter int DW /*verilator public*/ = 10,
  parameter int LATENCY = 20
) (
  input  wire         clk_i,
  input  wire         rst_ni,
  input  wire         en_i,
  // The frame's configuration (constant while its slots flow).
  input  wire         depth_en_i,   // OUTPUT.MODE = DEPTH
  input  wire  [23:0] focal_i,      // F: f in 1/256 px
  input  wire  [23:0] baseline_i,   // B: micrometres
  input  wire         start_i,      // the configuration was latched in this cycle
  input  wire         ready_i,      // the rest of the core is ready for the frame
  output logic        ready_o,      // that, and K = F B is ready
  // The result of the last stage (sgm_median5x5) and its frame-pixel flag.
  input  wire  [DW-1:0] disp_i,
  input  wire           valid_i,
  input  wire           in_valid_i,
  output logic [15:0]   word_o,
  output logic          out_valid_o
);

  // The pipeline's stages: the input registers, N and V, the saturation, 16 quotient bits, the word.
  localparam int STAGES = 3 + 16 + 1;

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(DW >= 5 && DW <= 15)) begin : g_bad_dw
    $error("sgm_depth: DW = %0d: DW must be from 5 to 15 (4 fractional bits; the disparity word has 15 data bits)", DW);
  end
  if (!(LATENCY == STAGES)) begin : g_bad_latency
    $error("sgm_depth: LATENCY = %0d: the latency is %0d slots (input registers, N and V, the saturation, 16 quotient bits, the word)", LATENCY, STAGES);
  end
`endif

  localparam int VW = DW + 14;  // V = 16000 dq < 2^14 2^DW
  localparam int NW = 49;       // N = K + 8000 dq < 2^48 + 2^(DW + 13)
  localparam int QB = 16;       // quotient bits
  localparam int RMAX = VW + QB;  // the remainder's widest (below V 2^16)
  // The side of every stage: {saturated, valid, disparity, quotient, V}.
  localparam int SIDE_W = 2 + DW + QB + VW;

  // ------------------------------------------------------------ K = F B
  logic [47:0] product_q, addend_q;
  logic [23:0] multiplier_q;
  logic        busy_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
    end else if (start_i) begin
      busy_q <= 1'b1;
    end else if (busy_q && multiplier_q == '0) begin
      busy_q <= 1'b0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (start_i) begin
      product_q    <= '0;
      addend_q     <= {24'd0, focal_i};
      multiplier_q <= baseline_i;
    end else if (busy_q) begin
      if (multiplier_q[0]) product_q <= product_q + addend_q;
      addend_q     <= {addend_q[46:0], 1'b0};
      multiplier_q <= {1'b0, multiplier_q[23:1]};
    end
  end

  assign ready_o = ready_i && !busy_q;

  // ------------------------------------------------------------ input, N and V
  logic          in_q, ok_q;
  logic [DW-1:0] disp_q;
  logic          nv_in_q, nv_ok_q;
  logic [DW-1:0] nv_disp_q;
  logic [NW-1:0] n_q;
  logic [VW-1:0] v_q;

  // 16000 dq = 2^14 dq - 2^8 dq - 2^7 dq; 8000 dq is half of it.
  wire [VW-1:0] v_d = (VW'(disp_q) << 14) - (VW'(disp_q) << 8) - (VW'(disp_q) << 7);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      in_q    <= 1'b0;
      nv_in_q <= 1'b0;
    end else if (en_i) begin
      in_q    <= in_valid_i;
      nv_in_q <= in_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ok_q      <= valid_i;
      disp_q    <= disp_i;
      nv_ok_q   <= ok_q;
      nv_disp_q <= disp_q;
      v_q       <= v_d;
      n_q       <= NW'(product_q) + NW'(v_d[VW-1:1]);
    end
  end

  // ------------------------------------------------------------ saturation
  // rem_w / side_w / in_w: stage i's input at index i + 1 (index QB + 1 .. 1),
  // its output at index i; the remainder at index i + 1 holds VW + i + 1 bits.
  logic [(QB+1)*RMAX-1:0]   rem_w;
  logic [(QB+1)*SIDE_W-1:0] side_w;
  logic [QB:0]              in_w;

  logic              sat_in_q;
  logic [RMAX-1:0]   sat_rem_q;
  logic [SIDE_W-1:0] sat_side_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) sat_in_q <= 1'b0;
    else if (en_i) sat_in_q <= nv_in_q;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sat_rem_q  <= n_q[RMAX-1:0];  // below V 2^16 unless saturated
      sat_side_q <= {n_q[NW-1:QB] >= (NW - QB)'(v_q), nv_ok_q, nv_disp_q, QB'(0), v_q};
    end
  end

  assign rem_w[QB*RMAX +: RMAX]       = sat_rem_q;
  assign side_w[QB*SIDE_W +: SIDE_W]  = sat_side_q;
  assign in_w[QB]                     = sat_in_q;

  // ------------------------------------------------------------ quotient bits
  for (genvar i = 0; i < QB; i++) begin : g_bit
    wire [VW+i:0]      rem_in  = rem_w[(i+1)*RMAX +: VW + i + 1];
    wire [SIDE_W-1:0]  side_in = side_w[(i+1)*SIDE_W +: SIDE_W];
    wire [VW-1:0]      v_in    = side_in[VW-1:0];
    wire [VW:0]        top     = rem_in[VW+i:i];            // below 2 V
    wire [VW:0]        diff    = top - {1'b0, v_in};
    wire               take    = !diff[VW];                 // top >= V: quotient bit i is 1
    logic              in_q_i;
    logic [SIDE_W-1:0] side_q;

    always_ff @(posedge clk_i) begin
      if (!rst_ni) in_q_i <= 1'b0;
      else if (en_i) in_q_i <= in_w[i+1];
    end

    always_ff @(posedge clk_i) begin
      if (en_i) side_q <= side_in | (SIDE_W'(take) << (VW + i));
    end

    if (i > 0) begin : g_rem
      logic [VW+i-1:0] rem_q;  // below V 2^i
      always_ff @(posedge clk_i) begin
        if (en_i) rem_q <= take ? {diff[VW-1:0], rem_in[i-1:0]} : rem_in[VW+i-1:0];
      end
      assign rem_w[i*RMAX +: RMAX] = RMAX'(rem_q);
    end else begin : g_last
      assign rem_w[RMAX-1:0] = '0;  // the remainder of the last bit is not needed
    end

    assign side_w[i*SIDE_W +: SIDE_W] = side_q;
    assign in_w[i]                    = in_q_i;
  end

  // ------------------------------------------------------------ the word
  wire [SIDE_W-1:0] last      = side_w[SIDE_W-1:0];
  wire [QB-1:0]     quotient  = last[VW +: QB];
  wire [DW-1:0]     last_disp = last[VW + QB +: DW];
  wire              last_ok   = last[VW + QB + DW];
  wire              saturated = last[VW + QB + DW + 1];
  wire [15:0]       depth     = saturated ? 16'hffff : quotient == '0 ? 16'd1 : quotient;
  wire [VW-1:0]     unused_v  = last[VW-1:0];

  always_ff @(posedge clk_i) begin
    if (!rst_ni) out_valid_o <= 1'b0;
    else if (en_i) out_valid_o <= in_w[0];
  end

  always_ff @(posedge clk_i) begin
    if (en_i) word_o <= !depth_en_i ? {last_ok, 15'(last_disp)} : last_ok ? depth : 16'd0;
  end

endmodule
`default_nettype wire
