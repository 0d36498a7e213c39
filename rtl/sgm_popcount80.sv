`default_nettype none
// sgm_popcount80: number of ones in an 80-bit census word (rank, and the
// Hamming distance of two signatures), as an adder tree: 2-, 3-, 4- and 5-bit
// levels, then a sum of 5 terms.
//
// Latency: 0 (combinational).
module sgm_popcount80 (
  input  wire  [79:0] bits_i,
  output logic [6:0]  count_o
);

  logic [79:0] l1;
  logic [59:0] l2;
  logic [39:0] l3;
  logic [24:0] l4;

  always_comb begin
    for (int i = 0; i < 40; i++) l1[i*2 +: 2] = {1'b0, bits_i[2*i]} + {1'b0, bits_i[2*i+1]};
    for (int i = 0; i < 20; i++) l2[i*3 +: 3] = {1'b0, l1[4*i +: 2]} + {1'b0, l1[4*i+2 +: 2]};
    for (int i = 0; i < 10; i++) l3[i*4 +: 4] = {1'b0, l2[6*i +: 3]} + {1'b0, l2[6*i+3 +: 3]};
    for (int i = 0; i < 5; i++) l4[i*5 +: 5] = {1'b0, l3[8*i +: 4]} + {1'b0, l3[8*i+4 +: 4]};
    count_o = {2'b0, l4[0 +: 5]} + {2'b0, l4[5 +: 5]} + {2'b0, l4[10 +: 5]} + {2'b0, l4[15 +: 5]} +
              {2'b0, l4[20 +: 5]};
  end

endmodule
`default_nettype wire
