// A stand-in for the Onboard SDK 4.1's MOP server (dji_mop_server.hpp, dji_mop_pipeline.hpp,
// dji_mop_pipeline_manager_base.hpp: the real headers, vendored in tests/vendor/dji/osdk-4.1.0/),
// beside fake_osdk.cpp (built with -DFAKE_OSDK_VERSION=41, whose Vehicle makes the mopServer from
// fake_osdk_mop_server()), written from what the headers say of the calls, so that OsdkMopLink
// runs end to end in tests. The pipeline is TCP on 127.0.0.1:$TTCTL_FAKE_MOP_PORT:
//  - MopServer::accept(id, type, p) (blocking): listens (once), accepts, and hands a new
//    MopPipeline; MopServer::close(id): shuts the pipeline's connection down (calls blocked on it
//    return) and deletes the pipeline at the next accept (the header: the server owns it);
//  - MopPipeline::sendData / recvData(DataPackType{data, length}, &len): send() / recv() of up to
//    length bytes, `len` brings back what moved; a closed peer is MOP_CONNECTIONCLOSE.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "dji_vehicle.hpp"

#if FAKE_OSDK_VERSION != 41
#error "the MOP stand-in is for the Onboard SDK 4.1 (-DFAKE_OSDK_VERSION=41)"
#endif

using DJI::OSDK::MopPipeline;
using DJI::OSDK::MopServer;
using DJI::OSDK::MOP::MopErrCode;
using DJI::OSDK::MOP::PipelineID;
using DJI::OSDK::MOP::PipelineType;

namespace {

std::mutex g_m;
int g_listen = -1;
std::vector<MopPipeline*> g_closed;  // closed pipelines, deleted at the next accept

int fd_of(const MopPipeline* p) { return static_cast<int>(reinterpret_cast<std::intptr_t>(p->channelHandle)); }

}  // namespace

namespace DJI {
namespace OSDK {

MopPipelineManagerBase::MopPipelineManagerBase() = default;
MopPipelineManagerBase::~MopPipelineManagerBase() = default;

MopServer::MopServer() : vehicle(nullptr) {}
MopServer::~MopServer() = default;

MopErrCode MopServer::accept(PipelineID id, PipelineType type, MopPipeline*& p)
{
    int listener = -1;
    {
        std::lock_guard<std::mutex> lock(g_m);
        for (MopPipeline* old : g_closed) {
            ::close(fd_of(old));
            delete old;
        }
        g_closed.clear();
        if (g_listen < 0) {
            const char* port = std::getenv("TTCTL_FAKE_MOP_PORT");
            const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
            const int one = 1;
            ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
            sockaddr_in a{};
            a.sin_family = AF_INET;
            a.sin_port = htons(static_cast<std::uint16_t>(port != nullptr ? std::atoi(port) : 0));
            a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
            if (port == nullptr || fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0
                || ::listen(fd, 4) != 0) {
                if (fd >= 0) {
                    ::close(fd);
                }
                return MOP::MOP_NOTREADY;
            }
            g_listen = fd;
        }
        listener = g_listen;
    }
    int fd = -1;
    do {
        fd = ::accept(listener, nullptr, nullptr);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) {
        return MOP::MOP_FAILED;
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    p = new MopPipeline(id, type);
    p->channelHandle = reinterpret_cast<void*>(static_cast<std::intptr_t>(fd));
    std::lock_guard<std::mutex> lock(g_m);
    pipelineMap[id] = p;
    return MOP::MOP_PASSED;
}

MopErrCode MopServer::close(PipelineID id)
{
    std::lock_guard<std::mutex> lock(g_m);
    auto it = pipelineMap.find(id);
    if (it == pipelineMap.end()) {
        return MOP::MOP_PARM;
    }
    ::shutdown(fd_of(it->second), SHUT_RDWR);
    g_closed.push_back(it->second);
    pipelineMap.erase(it);
    return MOP::MOP_PASSED;
}

MopPipeline::MopPipeline(PipelineID pid, PipelineType ptype) : channelHandle(nullptr), id(pid), type(ptype) {}
MopPipeline::~MopPipeline() = default;

MopErrCode MopPipeline::sendData(DataPackType dataPacket, uint32_t* len)
{
    if (dataPacket.data == nullptr || len == nullptr) {
        return MOP::MOP_PARM;
    }
    const ssize_t r = ::send(fd_of(this), dataPacket.data, std::min(*len, dataPacket.length), MSG_NOSIGNAL);
    if (r < 0) {
        *len = 0;
        return MOP::MOP_CONNECTIONCLOSE;
    }
    *len = static_cast<uint32_t>(r);
    return MOP::MOP_PASSED;
}

MopErrCode MopPipeline::recvData(DataPackType dataPacket, uint32_t* len)
{
    if (dataPacket.data == nullptr || len == nullptr) {
        return MOP::MOP_PARM;
    }
    ssize_t r = -1;
    do {
        r = ::recv(fd_of(this), dataPacket.data, std::min(*len, dataPacket.length), 0);
    } while (r < 0 && errno == EINTR);
    if (r <= 0) {
        *len = 0;
        return MOP::MOP_CONNECTIONCLOSE;
    }
    *len = static_cast<uint32_t>(r);
    return MOP::MOP_PASSED;
}

PipelineID MopPipeline::getId() { return id; }
PipelineType MopPipeline::getType() { return type; }

}  // namespace OSDK
}  // namespace DJI

std::map<PipelineID, MopPipeline*> pipelineMap;

DJI::OSDK::MopServer* fake_osdk_mop_server() { return new MopServer(); }

void fake_osdk_mop_server_free(DJI::OSDK::MopServer* server) { delete server; }
