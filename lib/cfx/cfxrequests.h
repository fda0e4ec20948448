// Answers to the requests that reach a workspace's CFX endpoints on their request queue, as the
// IPC's SDK answers them (CFX/Transport/AmqpRequestProcessor.cs, docs/cfx.md): AreYouThere and
// GetEndpointInformation for the endpoint the request names, the CFX "not supported" answer for
// any other request. The answer's Source is the endpoint, its Target the requester, its RequestID
// the request's; it goes to the request's reply-to address, uncompressed as the SDK's answers are,
// with the request's AMQP message-id as its correlation-id (what an SDK requester receives).
//
// A request is input from the network: bounded and checked by the envelope's own reader
// (Envelope::fromBytes), and one that names no endpoint of this workspace or gives no reply-to
// gets no answer, only the reason.
#pragma once

#include "cfxmessages.h"

#include "base/outcome.h"

namespace tipscope::cfx {

// What an endpoint says of itself (GetEndpointInformationResponse's Endpoint).
struct EndpointIdentity {
    QString handle;
    QString vendor;
    QString model;    // ModelNumber
    QString name;     // FriendlyName: where the station is reached
    QString firmware; // the station's software version
};

// Where requests reach the endpoints: the broker's URL and the queue.
struct RequestPlace {
    QString networkUri;
    QString address;
};

struct Answer {
    QString address; // the requester's reply-to
    AmqpMessage message;
};

[[nodiscard]] Message getEndpointInformationResponse(const EndpointIdentity &endpoint,
                                                     const RequestPlace &place);
// The answer to `request`, or why there is none.
[[nodiscard]] base::Outcome<Answer> answerRequest(const AmqpRequest &request,
                                                  const QList<EndpointIdentity> &endpoints,
                                                  const RequestPlace &place);

} // namespace tipscope::cfx
