# SPDX-License-Identifier: Apache-2.0
# Seeds of fuzz_rsi_config: the sample Ethernet config behind a 0 byte, the sample context behind a
# 1 byte (the byte chooses the reader). cmake -DOUT=DIR -DSOURCE=resources/rsi -P rsi_seeds.cmake
file(MAKE_DIRECTORY ${OUT})
file(READ ${SOURCE}/RSI_EthernetConfig.xml config)
file(READ ${SOURCE}/rci_axis_corr.rsi.xml context)
file(WRITE ${OUT}/ethernet_config "0${config}")
file(WRITE ${OUT}/context "1${context}")
