`default_nettype none
// sgm_cost_pe: matching cost C(p, d) of one disparity d (docs/algorithm.md
// section 3) from the left census/rank at x and the right census/rank at x - d:
//   rt      = |rank_L - rank_R|                      (mode 0)
//   rsad    = popcount(census_L xor census_R)        (mode 1)
//   unified = rt + rsad                              (mode 2, also 3)
//   outside_i (x - d < 0, decided by the caller): Cmax of the mode (80, 80, 160).
//
// Parameters: none (the disparity only enters through outside_i).
// Latency: 2 enabled cycles. Stage A registers |rank difference|, Hamming
// distance and the out-of-image flag of the slot; stage B selects by mode_i,
// which belongs to stage B's slot (the slot entered one enabled cycle earlier).
// Throughput: one cost per enabled cycle. No control registers, no reset.
module sgm_cost_pe (
  input  wire             clk_i,
  input  wire             en_i,
  input  wire  [1:0]      mode_i,
  input  wire  [79:0]     lcensus_i,
  input  wire  [6:0]      lrank_i,
  input  wire  [79:0]     rcensus_i,
  input  wire  [6:0]      rrank_i,
  input  wire             outside_i,
  output logic [7:0]      cost_o
);

  // Popcount of 80 bits as an adder tree (2, 3, 4, 5 bit levels, then 5 terms).
  function automatic logic [6:0] popcount80(input logic [79:0] v);
    logic [79:0] l1;
    logic [59:0] l2;
    logic [39:0] l3;
    logic [24:0] l4;
    l1 = '0;
    l2 = '0;
    l3 = '0;
    l4 = '0;
    for (int i = 0; i < 40; i++) l1[i*2 +: 2] = {1'b0, v[2*i]} + {1'b0, v[2*i+1]};
    for (int i = 0; i < 20; i++) l2[i*3 +: 3] = {1'b0, l1[4*i +: 2]} + {1'b0, l1[4*i+2 +: 2]};
    for (int i = 0; i < 10; i++) l3[i*4 +: 4] = {1'b0, l2[6*i +: 3]} + {1'b0, l2[6*i+3 +: 3]};
    for (int i = 0; i < 5; i++) l4[i*5 +: 5] = {1'b0, l3[8*i +: 4]} + {1'b0, l3[8*i+4 +: 4]};
    popcount80 = {2'b0, l4[0 +: 5]} + {2'b0, l4[5 +: 5]} + {2'b0, l4[10 +: 5]} + {2'b0, l4[15 +: 5]} +
                 {2'b0, l4[20 +: 5]};
  endfunction

  // Stage A
  logic [6:0] rt_q, ham_q;
  logic       out_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rt_q  <= lrank_i >= rrank_i ? lrank_i - rrank_i : rrank_i - lrank_i;
      ham_q <= popcount80(lcensus_i ^ rcensus_i);
      out_q <= outside_i;
    end
  end

  // Stage B
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      case (mode_i)
        2'd0:    cost_o <= out_q ? 8'd80  : {1'b0, rt_q};
        2'd1:    cost_o <= out_q ? 8'd80  : {1'b0, ham_q};
        default: cost_o <= out_q ? 8'd160 : {1'b0, rt_q} + {1'b0, ham_q};
      endcase
    end
  end

endmodule
`default_nettype wire
