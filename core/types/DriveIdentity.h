#pragma once

#include <QString>
#include <QtGlobal>

namespace learnid {

/// The CiA 301 identity object 0x1018 of a drive: sub 1 vendor id, 2 product code, 3 revision
/// number, 4 serial number (UNSIGNED32 each). Recorded in the parameter file, compared at
/// connect (docs/can-protocol.md §2.4).
struct DriveIdentity
{
    quint32 vendorId = 0;
    quint32 productCode = 0;
    quint32 revision = 0;
    quint32 serialNumber = 0;

    bool operator==(const DriveIdentity &o) const
    {
        return vendorId == o.vendorId && productCode == o.productCode && revision == o.revision &&
               serialNumber == o.serialNumber;
    }
    bool operator!=(const DriveIdentity &o) const { return !(*this == o); }

    /// "vendor 0x4c45494e, product 0x00000402, revision 0x00010000, serial 1001"
    QString text() const
    {
        const auto hex = [](quint32 v) {
            return QStringLiteral("0x%1").arg(v, 8, 16, QLatin1Char('0'));
        };
        return QStringLiteral("vendor %1, product %2, revision %3, serial %4")
            .arg(hex(vendorId), hex(productCode), hex(revision))
            .arg(serialNumber);
    }
};

} // namespace learnid
