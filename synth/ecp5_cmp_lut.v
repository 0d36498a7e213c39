// Yosys techmap for the ECP5 flow (synth/ecp5.tcl, SYNTH_ECP5_CMP_LUT = N):
// magnitude comparisons ($lt $le $gt $ge) of at most N bits as LUT logic
// instead of a CCU2C carry chain. Not RTL: a mapping file Yosys reads with
// `techmap -D SGM_CMP_LUT_MAX=N`; wider comparisons are left to synth_ecp5.
//
// Why: a carry chain on ECP5 costs, besides its CCU2Cs (two LUT positions
// each), a CCU2C that nextpnr adds in front of it (the constant carry-in) and
// one behind it (a comparison's result is the carry-out, which reaches the
// fabric only through another CCU2C): a 9-bit comparison packs into about 15
// LUT positions, as LUT logic into about 11.5 (synth/README.md, "What the
// slices hold").
//
// The comparison is x < y (x <= y for $le and $ge) as a tree of (less, equal)
// pairs over the bits; $gt and $ge swap the operands; signed operands compare
// with their sign bits inverted. abc maps the tree into LUT4s.
(* techmap_celltype = "$lt $le $gt $ge" *)
module _sgm_cmp_lut (A, B, Y);
  parameter A_SIGNED = 0;
  parameter B_SIGNED = 0;
  parameter A_WIDTH = 1;
  parameter B_WIDTH = 1;
  parameter Y_WIDTH = 1;
  parameter _TECHMAP_CELLTYPE_ = "";

  input  [A_WIDTH-1:0] A;
  input  [B_WIDTH-1:0] B;
  output [Y_WIDTH-1:0] Y;

  // Verilog compares signed only when both operands are signed.
  localparam SIGNED = A_SIGNED && B_SIGNED;
  localparam W = A_WIDTH > B_WIDTH ? A_WIDTH : B_WIDTH;
  localparam SWAP = _TECHMAP_CELLTYPE_ == "$gt" || _TECHMAP_CELLTYPE_ == "$ge";
  localparam OREQ = _TECHMAP_CELLTYPE_ == "$le" || _TECHMAP_CELLTYPE_ == "$ge";

  wire _TECHMAP_FAIL_ = W > `SGM_CMP_LUT_MAX;

  wire [W-1:0] a_ext, b_ext;
  generate
    if (SIGNED) begin : g_signed
      assign a_ext = $signed(A);
      assign b_ext = $signed(B);
    end else begin : g_unsigned
      assign a_ext = A;
      assign b_ext = B;
    end
  endgenerate

  wire [W-1:0] flip = SIGNED ? {1'b1, {(W - 1){1'b0}}} : {W{1'b0}};
  wire [W-1:0] x = (SWAP ? b_ext : a_ext) ^ flip;
  wire [W-1:0] y = (SWAP ? a_ext : b_ext) ^ flip;

  // Per bit (less, equal), combined pairwise in a balanced tree of log2(W)
  // levels (the higher half decides unless it is equal): abc keeps a
  // ripple nearly serial (seven LUT4 levels for nine bits in the engine), the
  // tree gives it the short form to start from.
  localparam N = 1 << $clog2(W);
  wire [2*N-2:0] lt_t, eq_t;  // node i: children 2i + 1 (low), 2i + 2 (high)
  genvar i;
  generate
    for (i = 0; i < N; i = i + 1) begin : g_leaf
      if (i < W) begin : g_bit
        assign lt_t[N - 1 + i] = ~x[i] & y[i];
        assign eq_t[N - 1 + i] = ~(x[i] ^ y[i]);
      end else begin : g_pad
        assign lt_t[N - 1 + i] = 1'b0;
        assign eq_t[N - 1 + i] = 1'b1;
      end
    end
    for (i = 0; i < N - 1; i = i + 1) begin : g_node
      assign lt_t[i] = lt_t[2*i + 2] | (eq_t[2*i + 2] & lt_t[2*i + 1]);
      assign eq_t[i] = eq_t[2*i + 2] & eq_t[2*i + 1];
    end
  endgenerate

  assign Y = {{(Y_WIDTH - 1){1'b0}}, OREQ ? lt_t[0] | eq_t[0] : lt_t[0]};
endmodule
