#include "local_http_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "airshape/error.h"

namespace airshape::cli {

namespace {

const char* reasonOf(int status) {
  switch (status) {
    case 200:
      return "OK";
    case 404:
      return "Not Found";
    case 400:
      return "Bad Request";
    case 405:
      return "Method Not Allowed";
    default:
      return "Error";
  }
}

void sendAll(int socket, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(socket, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return;  // the browser went away: nothing to do about it
    sent += static_cast<std::size_t>(n);
  }
}

}  // namespace

LocalHttpServer::LocalHttpServer(int port) {
  listening_ = ::socket(AF_INET, SOCK_STREAM, 0);
  if (listening_ < 0) throw Error(ErrorCode::WriteFailed, std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(listening_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // this machine only
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(listening_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(listening_, 16) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listening_);
    throw Error(ErrorCode::InvalidArgument, "cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
  }
  socklen_t length = sizeof address;
  ::getsockname(listening_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
}

LocalHttpServer::~LocalHttpServer() {
  if (connection_ >= 0) ::close(connection_);
  if (listening_ >= 0) ::close(listening_);
}

std::optional<LocalHttpServer::Request> LocalHttpServer::next(int milliseconds) {
  pollfd waiting{listening_, POLLIN, 0};
  if (::poll(&waiting, 1, milliseconds) <= 0) return std::nullopt;
  connection_ = ::accept(listening_, nullptr, nullptr);
  if (connection_ < 0) return std::nullopt;
  // The request line and headers; a body (none is expected) is not read.
  std::string head;
  char buffer[4096];
  while (head.find("\r\n\r\n") == std::string::npos && head.size() < 65536) {
    pollfd reading{connection_, POLLIN, 0};
    if (::poll(&reading, 1, 2000) <= 0) break;
    const ssize_t n = ::recv(connection_, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    head.append(buffer, static_cast<std::size_t>(n));
  }
  Request request;
  std::istringstream line(head.substr(0, head.find("\r\n")));
  line >> request.method >> request.path;
  if (const std::size_t question = request.path.find('?'); question != std::string::npos) {
    request.query = request.path.substr(question + 1);
    request.path.erase(question);
  }
  return request;
}

std::optional<std::string> LocalHttpServer::parameter(const std::string& query, const std::string& name) {
  std::istringstream pairs(query);
  std::string pair;
  while (std::getline(pairs, pair, '&')) {
    const std::size_t equals = pair.find('=');
    if (pair.substr(0, equals) != name) continue;
    const std::string encoded = equals == std::string::npos ? "" : pair.substr(equals + 1);
    std::string value;
    for (std::size_t i = 0; i < encoded.size(); ++i) {
      if (encoded[i] == '+') {
        value += ' ';
      } else if (encoded[i] == '%' && i + 2 < encoded.size() &&
                 std::isxdigit(static_cast<unsigned char>(encoded[i + 1])) &&
                 std::isxdigit(static_cast<unsigned char>(encoded[i + 2]))) {
        value += static_cast<char>(std::stoi(encoded.substr(i + 1, 2), nullptr, 16));
        i += 2;
      } else {
        value += encoded[i];
      }
    }
    return value;
  }
  return std::nullopt;
}

void LocalHttpServer::respond(const Response& response) {
  if (connection_ < 0) return;
  std::ostringstream head;
  head << "HTTP/1.0 " << response.status << ' ' << reasonOf(response.status) << "\r\n"
       << "Content-Type: " << response.contentType << "\r\n"
       << "Content-Length: " << response.body.size() << "\r\n"
       << "Cache-Control: no-store\r\nConnection: close\r\n\r\n";
  sendAll(connection_, head.str());
  sendAll(connection_, response.body);
  ::close(connection_);
  connection_ = -1;
}

}  // namespace airshape::cli
