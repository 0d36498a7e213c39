// SPDX-License-Identifier: Apache-2.0
// Yosys techmap for the ECP5 flow (synth/ecp5.tcl, SYNTH_ECP5_CMP_LUT = N):
// magnitude comparisons ($lt $le $gt $ge) of at most N bits as LUT logic
// instead of a CCU2C carry chain. Not RTL: a mapping file Yosys reads with
// `techmap -D SGM_CMP_LUT_MAX=N`; wider comparisons are left to synth_ecp5.
//
// Why: a carry chain on ECP5 costs, besides its CCU2Cs (two LUT positions
// each), a CCU2C that nextpnr adds in front of it (the constant carry-in) and
// one behind it (a comparison's result is the carry-out, which reaches the
// fabric only through another CCU2C): a 9-bit comparison packs into about 15
// LUT positions, as LUT logic into about 11.5 (docs/notes/synthesis-log.md, "What the
// slices hold").
//
// The comparison is the ripple x < y from the least significant bit:
// c[i + 1] = (~x[i] & y[i]) | (x[i] xnor y[i]) & c[i], c[0] = 1 for <= and >=;
// $gt and $ge swap the operands; signed operands compare with their sign bits
// inverted. abc restructures the ripple into LUT4s.
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

  wire [W:0] c;
  assign c[0] = OREQ ? 1'b1 : 1'b0;
  genvar i;
  generate
    for (i = 0; i < W; i = i + 1) begin : g_bit
      assign c[i + 1] = (~x[i] & y[i]) | (~(x[i] ^ y[i]) & c[i]);
    end
  endgenerate

  assign Y = {{(Y_WIDTH - 1){1'b0}}, c[W]};
endmodule
