"""TLS 1.3 on the agent's TCP transport (Python's ``ssl``), with a certificate the agent makes itself.

On its first start the agent makes a key (ECDSA P-256) and a self-signed certificate for it in its folder
(``agent_certificate``; both mode 0600, made with the pinned ``cryptography`` package). No authority vouches for
it: a laptop takes the certificate it meets when it pairs (as ssh takes a host key it has not seen) and keeps its
SHA-256 (``fingerprint``) with its key; from then on a certificate with another fingerprint is refused. Why and
what that does not protect: docs/agent.md, "Who may use the agent", and docs/decisions/035.
"""
import hashlib
import socket
import ssl
from datetime import datetime, timedelta, timezone
from pathlib import Path

from rockly_desktop.runtime.agent.private_files import held, private_folder, write_private

CERTIFICATE, PRIVATE_KEY, LOCK = "tls-certificate.pem", "tls-key.pem", "tls.lock"
VALID_DAYS = 20 * 365  # a robot's certificate outlives the robot: pinned, it needs no renewal
TLS_HANDSHAKE = 0x16  # the first byte a TLS client sends; a plain JSON line starts with "{"


def agent_certificate(folder: Path) -> tuple:
    """``(certificate path, key path)`` of the agent's own, made on the first call (by the agent or by
    ``rockly agent pair``, whichever comes first: the two never both make one)."""
    folder = private_folder(folder)
    certificate, key = folder / CERTIFICATE, folder / PRIVATE_KEY
    with held(folder / LOCK):
        if not (certificate.exists() and key.exists()):
            _make_certificate(certificate, key)
    return certificate, key


def _make_certificate(certificate: Path, key_path: Path):
    from cryptography import x509
    from cryptography.hazmat.primitives import hashes, serialization
    from cryptography.hazmat.primitives.asymmetric import ec
    from cryptography.x509.oid import NameOID

    key = ec.generate_private_key(ec.SECP256R1())
    name = x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, f"Rockly agent on {socket.gethostname()}"[:64])])
    now = datetime.now(timezone.utc)
    made = (x509.CertificateBuilder().subject_name(name).issuer_name(name).public_key(key.public_key())
            .serial_number(x509.random_serial_number()).not_valid_before(now - timedelta(days=1))
            .not_valid_after(now + timedelta(days=VALID_DAYS))
            .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
            .sign(key, hashes.SHA256()))
    write_private(key_path, key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                                              serialization.NoEncryption()))
    write_private(certificate, made.public_bytes(serialization.Encoding.PEM))


def server_context(folder: Path) -> ssl.SSLContext:
    """The agent's TLS 1.3 (nothing older) context with its own certificate."""
    certificate, key = agent_certificate(folder)
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
    context.minimum_version = ssl.TLSVersion.TLSv1_3
    context.load_cert_chain(str(certificate), str(key))
    return context


def client_context() -> ssl.SSLContext:
    """A client's TLS 1.3 context. It checks no authority or host name: the agent's certificate is self-signed,
    and the client compares its fingerprint with the one it pinned at pairing (``fingerprint``) instead."""
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT)
    context.minimum_version = ssl.TLSVersion.TLSv1_3
    context.check_hostname = False
    context.verify_mode = ssl.CERT_NONE
    return context


def fingerprint(certificate_der: bytes) -> str:
    """The SHA-256 of a certificate (DER), as hex: what a laptop pins."""
    return hashlib.sha256(certificate_der).hexdigest()


def folder_fingerprint(folder: Path) -> str:
    """The fingerprint of the agent's certificate in ``folder`` (made if it has none yet)."""
    certificate, _ = agent_certificate(folder)
    return fingerprint(ssl.PEM_cert_to_DER_cert(certificate.read_text(encoding="ascii")))


def short_fingerprint(hex_fingerprint: str) -> str:
    """The first 64 bits of a fingerprint in four groups (``3F2A 9C01 77DE 4B10``): for a person to compare what
    the robot and the laptop show."""
    head = hex_fingerprint[:16].upper()
    return " ".join(head[i:i + 4] for i in range(0, len(head), 4))
