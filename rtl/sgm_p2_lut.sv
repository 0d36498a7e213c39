// SPDX-License-Identifier: Apache-2.0
`default_nettype none
// sgm_p2_lut: the adaptive P2 table of docs/algorithm.md section 4, k = 0 .. 255,
//   knee  (mode 0): P2r(k) = max(P1, floor(4 P2' / (k + 4)))
//   paper (mode 1): P2r(k) = max(P1, floor(P2' / k)),  P2r(0) = max(P1, P2')
// filled after start_i by one iterative divider: with N = 4 P2' (knee) or P2'
// (paper) and, for k = 0, 1, .., the divisor k + 4 (knee) or k (paper), it keeps
// q = floor(N / divisor) and prod = q * divisor (q starts at P2': 4 P2' / 4 and
// the paper's P2' at k = 0), decrementing q (prod -= divisor) while prod > N,
// then writing entry k and moving on with prod += q. At most 256 + 255 + 1
// cycles; ready_o rises when done.
//
// Parameters: PW penalty width (P1, P2' and the entries).
// Latency: lookups are registered (one enabled cycle). Throughput: NPORTS
// lookups per enabled cycle.
module sgm_p2_lut #(
  parameter int PW     = 8,
  parameter int NPORTS = 4
) (
  input  wire                   clk_i,
  input  wire                   rst_ni,
  // Fill control: start_i (one cycle) latches p1_i / p2_i and refills the table.
  input  wire                   start_i,
  input  wire  [PW-1:0]         p1_i,
  input  wire  [PW-1:0]         p2_i,
  input  wire                   mode_i,   // 0 knee, 1 paper (latched with start_i)
  output logic                  ready_o,
  // Lookups: index |dI| per port, result P2r per port, updated when en_i.
  input  wire                   en_i,
  input  wire  [NPORTS*8-1:0]   idx_i,
  output logic [NPORTS*PW-1:0]  p2r_o
);

  // ------------------------------------------------------------ parameter checks
  // An illegal parameter value stops elaboration with a message naming it ($error in
  // a generate block: Verilator and Yosys; Icarus 11 has no elaboration system tasks,
  // so its builds, of legal parameters only, leave the checks out).
`ifndef __ICARUS__
  if (!(PW >= 1)) begin : g_bad_pw
    $error("sgm_p2_lut: PW = %0d: PW must be at least 1", PW);
  end
  if (!(NPORTS >= 1)) begin : g_bad_nports
    $error("sgm_p2_lut: NPORTS = %0d: NPORTS must be at least 1", NPORTS);
  end
`endif

  logic [PW-1:0] table_q [0:255];

  logic          busy_q;
  logic [8:0]    k_q;        // 0 .. 255
  logic [PW-1:0] q_q;        // floor(N / (k + 4)) once prod_q <= N
  logic [PW+2:0] prod_q;     // q_q * (k_q + 4), at most N + q_q < 5 P2'
  logic [PW-1:0] p1_q, p2_q;
  logic          paper_q;

  wire [PW+2:0]    num     = paper_q ? (PW+3)'(p2_q) : {1'b0, p2_q, 2'b00};  // N = P2' or 4 P2'
  wire [PW+2:0]    den     = (PW+3)'(k_q) + (paper_q ? (PW+3)'(0) : (PW+3)'(4));
  wire             too_big = prod_q > num;
  wire [PW-1:0]    entry   = q_q > p1_q ? q_q : p1_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q  <= 1'b0;
      ready_o <= 1'b0;
    end else if (start_i) begin
      busy_q  <= 1'b1;
      ready_o <= 1'b0;
      p1_q    <= p1_i;
      p2_q    <= p2_i;
      paper_q <= mode_i;
      k_q     <= 9'd0;
      q_q     <= p2_i;
      prod_q  <= mode_i ? '0 : {1'b0, p2_i, 2'b00};  // q * divisor at k = 0
    end else if (busy_q) begin
      if (too_big) begin
        q_q    <= q_q - 1'b1;
        prod_q <= prod_q - den;
      end else begin
        k_q    <= k_q + 1'b1;
        prod_q <= prod_q + {3'b000, q_q};
        if (k_q == 9'd255) begin
          busy_q  <= 1'b0;
          ready_o <= 1'b1;
        end
      end
    end
  end

  // One write port: entry k when q is settled.
  always_ff @(posedge clk_i) begin
    if (busy_q && !too_big) table_q[k_q[7:0]] <= entry;
  end

  for (genvar p = 0; p < NPORTS; p++) begin : g_port
    always_ff @(posedge clk_i) begin
      if (en_i) p2r_o[p*PW +: PW] <= table_q[idx_i[p*8 +: 8]];
    end
  end

endmodule
`default_nettype wire
