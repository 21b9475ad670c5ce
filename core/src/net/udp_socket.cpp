// SPDX-License-Identifier: Apache-2.0
// POSIX implementation of UdpSocket: poll() for the timeout, MSG_TRUNC to detect oversize datagrams.
#include "net/udp_socket.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace xmate::net {

std::string Endpoint::toString() const {
  char buf[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &addr.sin_addr, buf, sizeof buf);
  return std::string(buf) + ":" + std::to_string(ntohs(addr.sin_port));
}

Endpoint makeEndpoint(const std::string& ip, uint16_t port) {
  Endpoint e;
  e.addr.sin_family = AF_INET;
  e.addr.sin_port = htons(port);
  const std::string host = ip == "localhost" ? "127.0.0.1" : ip;
  if (inet_pton(AF_INET, host.c_str(), &e.addr.sin_addr) != 1)
    throw std::invalid_argument("'" + ip + "' is not an IPv4 address (expected e.g. 192.168.0.160)");
  return e;
}

UdpSocket::~UdpSocket() { close(); }

UdpSocket::UdpSocket(UdpSocket&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

UdpSocket& UdpSocket::operator=(UdpSocket&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

void UdpSocket::bind(const std::string& ip, uint16_t port) {
  close();
  const Endpoint local = makeEndpoint(ip, port);
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error(std::string("cannot open a UDP socket: ") + std::strerror(errno));
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local.addr), sizeof local.addr) != 0) {
    const int err = errno;
    close();
    throw std::runtime_error("cannot bind UDP " + local.toString() + ": " + std::strerror(err));
  }
}

uint16_t UdpSocket::localPort() const {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  if (fd_ < 0 || ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) != 0) return 0;
  return ntohs(a.sin_port);
}

void UdpSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void UdpSocket::setBufferSizes(int receive_bytes, int send_bytes) {
  if (fd_ < 0) return;
  ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_bytes, sizeof receive_bytes);
  ::setsockopt(fd_, SOL_SOCKET, SO_SNDBUF, &send_bytes, sizeof send_bytes);
}

long UdpSocket::sendTo(const Endpoint& to, const void* data, size_t size) {
  return ::sendto(fd_, data, size, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&to.addr), sizeof to.addr);
}

long UdpSocket::receiveFrom(void* data, size_t capacity, Endpoint* from, int64_t timeout_us) {
  if (timeout_us >= 0) {
    pollfd p{fd_, POLLIN, 0};
    timespec ts{timeout_us / 1'000'000, long(timeout_us % 1'000'000) * 1000};
    const int r = ::ppoll(&p, 1, &ts, nullptr);
    if (r == 0) return 0;
    if (r < 0) return errno == EINTR ? 0 : -1;
  }
  sockaddr_in src{};
  socklen_t len = sizeof src;
  const long n = ::recvfrom(fd_, data, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&src), &len);
  if (n < 0) return (errno == EAGAIN || errno == EINTR) ? 0 : -1;
  if (from) from->addr = src;
  return n;
}

}  // namespace xmate::net
