#pragma once

namespace learnid {

/// Sets TCP_NODELAY on every TCP socket this process has open and returns how many it set.
/// The `virtualcan` plugin carries CAN frames over TCP without it, and its server (hosted by
/// whichever process opened the port first) keeps its sockets to itself: Nagle's algorithm then
/// holds a frame written within one round trip of the previous one for up to 40 ms, and several
/// SYNC periods' frames arrive at once. Call it after connecting and again when peers may have
/// connected (the server's sockets appear then). Linux only; elsewhere it does nothing.
int setNoDelayOnAllTcpSockets();

} // namespace learnid
