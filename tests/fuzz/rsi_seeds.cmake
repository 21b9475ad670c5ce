# SPDX-License-Identifier: Apache-2.0
# Seeds of fuzz_rsi_config: the sample Ethernet config behind a 0 byte, the sample context behind a
# 1 byte (the byte chooses the reader). cmake -DOUT=DIR -DSOURCE=resources/rsi -P rsi_seeds.cmake
file(MAKE_DIRECTORY ${OUT})
file(READ ${SOURCE}/RSI_EthernetConfig.xml config)
file(READ ${SOURCE}/rci_axis_corr.rsi.xml context)
file(WRITE ${OUT}/ethernet_config "0${config}")
file(WRITE ${OUT}/context "1${context}")
# fuzz_rsi_datagram: a <Rob> as a KRC sends it.
file(MAKE_DIRECTORY ${OUT}_datagram)
file(WRITE ${OUT}_datagram/rob "<Rob Type=\"ImFree\"><RIst X=\"445.0\" Y=\"0.0\" Z=\"810.0\" A=\"180.0\" B=\"0.0\" C=\"180.0\" /><AIPos A1=\"0.0\" A2=\"-90.0\" A3=\"90.0\" A4=\"0.0\" A5=\"90.0\" A6=\"0.0\" /><Delay D=\"0\" /><Tech C11=\"1\" C12=\"2\" /><In b=\"1\" /><Msg>hello</Msg><Count>3</Count><IPOC>123456</IPOC></Rob>")
